#!/usr/bin/env bash
# QuadGraph's physical error (Fig. 11/13 of quadgraph-diffusion): the K and level sweep against the
# volumetric path tracer (multiple scattering only, subsurface part, as the diffusion equation models),
# with the dipole (--method reference) swept in the same run as the baseline.
# usage: bench/quadgraph_vs_pathtrace.sh [BUILD_DIR] [OUT_DIR]   (defaults: build docs/accuracy/quadgraph)
set -euo pipefail
BUILD=${1:-build}
OUT=${2:-docs/accuracy/quadgraph}
mkdir -p "$OUT"
RES=64
SPP=1024
for case in "sphere 30 skin1" "sphere 30 marble" "sphere 30 spectralon" "sphere 10 skin1" "torus 30 skin1"; do
  read -r shape size material <<<"$case"
  tag="vs-pathtrace-$shape-$size-$material"
  echo "== $tag" >&2
  "$BUILD/lucent" bench --quiet --shape "$shape" --size-mm "$size" --material "$material" --light env:uniform \
    --width $RES --height $RES \
    --reference-method pathtrace --reference-knob subsurface=1 --reference-knob orders=multiple \
    --reference-knob spp=$SPP \
    --method quadgraph --sweep K=2,1,0.5,0.25 --sweep levels=1,2 \
    --baseline-method reference --baseline-sweep fraction=1,0.25 \
    --csv "$OUT/$tag.csv" --plot "$OUT/$tag.png" | tee "$OUT/$tag.txt"
done
