#!/usr/bin/env bash
# The stage table of docs/performance.md, measured in one go: each hot stage's figure from its
# benchmark or from `lucent render --stats`, twice where the table gives a range, after the
# machine's roofline (rd_kernel_bench measures it in its own process). Prints one line a stage;
# the flops and bytes a unit that turn them into the table's rates are stated in the table.
# About 70 s on 2 cores (the renders write their pictures to a temporary folder). Usage: bench/stage_table.sh [build-dir]
set -euo pipefail
build=${1:-build}
lucent="$build/lucent"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The figures of a stats file, as NAME=VALUE (the CLI's JSON; Debian's python3 reads it).
figures() {
  /usr/bin/python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
print(" ".join("%s=%.4g" % (k, d["figures"][k]) for k in sys.argv[2:]))' "$@"
}
render() {  # render NAME FIGURE... -- ARGS...: two runs, the named figures of each
  local name=$1; shift
  local keys=()
  while [[ $# -gt 0 && $1 != -- ]]; do keys+=("$1"); shift; done
  [[ $# -gt 0 ]] || { echo "stage_table.sh: render $name needs -- before its arguments" >&2; exit 2; }
  shift
  local vals
  for run in 1 2; do
    if ! "$lucent" render "$@" --stats "$work/s.json" --out "$work/o.exr" > /dev/null 2> "$work/err"; then
      echo "stage_table.sh: lucent render $* failed:" >&2
      cat "$work/err" >&2
      exit 1
    fi
    vals=$(figures "$work/s.json" "${keys[@]}")
    echo "$name (run $run): $vals"
  done
}

echo "== roofline, Rd sum and table sum (one thread)"
"$build/bench/rd_kernel_bench"
echo "== PRT frame's dot products"
"$build/bench/prt_dot_bench" | tail -n 4
echo "== stages read from lucent render --stats (2 threads)"
render "tsis rd=exact sum" evaluation_seconds -- --method tsis --knob samples=1600 --knob rd=exact
render "tsis table sum, sampling, atlas surface and irradiance" evaluation_seconds \
  sampling_seconds atlas_surface_seconds irradiance_seconds -- --method tsis --knob samples=1600
render "ring filter (tsm)" evaluation_seconds -- --method tsm
render "Jensen-Buhler octree" evaluation_seconds rd_terms -- --method jensen-buhler
render "path tracer" frame_seconds camera_samples scatter_events -- --shape sphere --size-mm 30 \
  --material marble --light env:uniform --width 64 --height 64 --method pathtrace \
  --knob spp=256 --knob boundary=fresnel
echo "== QuadGraph Jacobi iterations"
"$build/bench/quadgraph_bench" "$work/quadgraph" | grep -A12 "| node order"
