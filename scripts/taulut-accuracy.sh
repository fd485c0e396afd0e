#!/usr/bin/env bash
# The voxel optical-thickness LUT (taulut) and the voxel single-scattering estimator (voxel-single)
# against the path tracer on the paper's two scenes (a cube with a spherical cavity, a bottle of
# liquid), back-lit and index-matched (eta 1: the path tracer then reaches the sun directly, single
# scattering included), for a high-, a low- and a near-zero-albedo medium; then taulut's storage,
# precision and tap trades. Prints the markdown tables of docs/accuracy/taulut.md; leaves the images
# in OUT (and OUT/montage-*.png when Python's PIL is there).
#   usage: scripts/taulut-accuracy.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build}
out=${2:-/tmp/lucent-taulut-accuracy}
lucent="$build/lucent"
mkdir -p "$out"
size=160
spp=${LUCENT_TAULUT_SPP:-256}
view=(--light dir:0,0,-1 --view 0,0,1 --width $size --height $size --eta 1.0 --quiet)
truth=(--method pathtrace --knob spp=$spp --knob subsurface=1 --knob boundary=matched)

json() { /usr/bin/python3 -c "import json,sys; print('%.3g' % (json.load(open(sys.argv[1]))$2))" "$1"; }
compare() {  # test reference -> "ratio_r / g / b | rel_rms | scaled_rel_rms"
  "$lucent" compare "$1" "$2" --json | /usr/bin/python3 -c '
import json, sys
j = json.load(sys.stdin)
print("%.3g / %.3g / %.3g | %.3g | %.3g" % (j["mean_ratio_r"], j["mean_ratio_g"], j["mean_ratio_b"],
      j["relative_rms"], j["scaled_relative_rms"]))'
}
render() {  # name scene-args... : renders OUT/name.{exr,png,json}
  local name=$1
  shift
  "$lucent" render "$@" "${view[@]}" --out "$out/$name.exr" --out "$out/$name.png" \
    --stats "$out/$name.json"
}
row() {  # label medium technique knobs test-image reference-image seconds
  echo "| $1 | $2 | $3 | $4 | $(compare "$out/$5.exr" "$out/$6.exr") | $7 |"
}

echo "| scene | medium | technique vs truth | knobs | mean ratio R / G / B | rel. RMS | scaled rel. RMS | s |"
echo "|---|---|---|---|---|---|---|---|"
run_case() {  # tag label medium-label scene-args...
  local tag=$1 label=$2 medium=$3
  shift 3
  render "$tag-pt-all" "$@" "${truth[@]}"
  render "$tag-pt-single" "$@" "${truth[@]}" --knob orders=single
  for v in 25 60; do
    render "$tag-taulut-$v" "$@" --method taulut --knob voxels=$v --knob map=1024 \
      --knob storage=$([ $v = 60 ] && echo hierarchical || echo lut)
    local s
    s=$(json "$out/$tag-taulut-$v.json" '["wall_seconds"]')
    row "$label" "$medium" "taulut vs all orders" "voxels=$v" "$tag-taulut-$v" "$tag-pt-all" "$s"
    row "$label" "$medium" "taulut vs single" "voxels=$v" "$tag-taulut-$v" "$tag-pt-single" "$s"
  done
  render "$tag-single" "$@" --method voxel-single
  row "$label" "$medium" "voxel-single vs single" "voxels=60" "$tag-single" "$tag-pt-single" \
    "$(json "$out/$tag-single.json" '["wall_seconds"]')"
  row "$label" "$medium" "pathtrace single vs all orders" "spp=$spp" "$tag-pt-single" \
    "$tag-pt-all" "$(json "$out/$tag-pt-all.json" '["wall_seconds"]')"
}

cube=(--shape cube-cavity --size-mm 10)
run_case cube-milk "cube with cavity, 10 mm" "Skimmilk" "${cube[@]}" --material Skimmilk
run_case cube-juice "cube with cavity, 10 mm" "Ruby Grapefruit Juice" "${cube[@]}" \
  --material "Ruby Grapefruit Juice"
run_case cube-wine "cube with cavity, 10 mm" "Merlot" "${cube[@]}" --material Merlot
bottle=(--shape bottle --size-mm 30 --material Skimmilk)
run_case bottle-wine "Skimmilk bottle, 30 mm" "Merlot inside" "${bottle[@]}" --fill Merlot
run_case bottle-juice "Skimmilk bottle, 30 mm" "Ruby Grapefruit Juice inside" "${bottle[@]}" \
  --fill "Ruby Grapefruit Juice"
# Fig. 2's comparison: translucent shadow maps see only the surface (no inner medium).
render bottle-tsm "${bottle[@]}" --fill none --method tsm --knob map=1024

echo
echo "| storage | precision | prepare s | frame s | table MiB | rel. RMS vs the exact walk | rel. RMS vs pathtrace |"
echo "|---|---|---|---|---|---|---|"
milk=("${cube[@]}" --material Skimmilk)
render store-exact "${milk[@]}" --method taulut --knob voxels=60 --knob storage=march \
  --knob map=1024
for spec in lut:fp16 lut:fp32 hierarchical:fp16:2 hierarchical:fp16:4 hierarchical:fp16:8 march:-; do
  IFS=: read -r storage precision cluster <<<"$spec"
  knobs=(--knob voxels=60 --knob storage=$storage --knob map=1024)
  [ "$precision" != - ] && knobs+=(--knob precision=$precision)
  [ -n "${cluster:-}" ] && knobs+=(--knob cluster=$cluster)
  name="store-$storage-$precision-${cluster:-0}"
  render "$name" "${milk[@]}" --method taulut "${knobs[@]}"
  exact=$("$lucent" compare "$out/$name.exr" "$out/store-exact.exr" --json |
    /usr/bin/python3 -c 'import json,sys; print("%.2g" % json.load(sys.stdin)["relative_rms"])')
  vs=$("$lucent" compare "$out/$name.exr" "$out/cube-milk-pt-all.exr" --json |
    /usr/bin/python3 -c 'import json,sys; print("%.3g" % json.load(sys.stdin)["relative_rms"])')
  echo "| $storage${cluster:+ (cluster $cluster)} | $precision |" \
    "$(json "$out/$name.json" '["figures"]["prepare_seconds"]') |" \
    "$(json "$out/$name.json" '["figures"]["frame_seconds"]') |" \
    "$(json "$out/$name.json" '["figures"]["table_bytes"] / 2**20') | $exact | $vs |"
done

echo
echo "| taps (rings) | frame s | rel. RMS vs pathtrace | scaled rel. RMS |"
echo "|---|---|---|---|"
for rings in 1 2 4 8 16; do
  name="taps-$rings"
  render "$name" "${milk[@]}" --method taulut --knob voxels=40 --knob rings=$rings --knob map=1024
  echo "| $((1 + 5 * rings)) ($rings) | $(json "$out/$name.json" '["figures"]["frame_seconds"]') |" \
    "$("$lucent" compare "$out/$name.exr" "$out/cube-milk-pt-all.exr" --json |
      /usr/bin/python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.3g | %.3g" % (j["relative_rms"], j["scaled_relative_rms"]))') |"
done

echo
echo "| scene | voxels | storage | prepare s | frame s (512 x 512 pixels, 1024^2 map, 2 cores) | frames/s |"
echo "|---|---|---|---|---|---|"
for scene in cube-cavity bottle; do
  for v in 25 60; do
    storage=$([ $v = 60 ] && echo hierarchical || echo lut)
    "$lucent" render --shape $scene --size-mm 10 --material Skimmilk --method taulut \
      --knob voxels=$v --knob storage=$storage --knob map=1024 --light dir:0,0,-1 --view 0,0.3,1 \
      --width 512 --height 512 --quiet --out "$out/frame.exr" --stats "$out/frame.json"
    f=$(json "$out/frame.json" '["figures"]["frame_seconds"]')
    echo "| $scene | $v | $storage | $(json "$out/frame.json" '["figures"]["prepare_seconds"]') |" \
      "$f | $(/usr/bin/python3 -c "print('%.3g' % (1 / $f))") |"
  done
done

# Side-by-side pictures, each tone-mapped to its own average (the paper's s / (1 + s)).
/usr/bin/python3 - "$out" <<'EOF' || echo "(no montage: Python's PIL is missing)" >&2
import sys
from PIL import Image, ImageDraw
out = sys.argv[1]
rows = {
    "cube": [("cube-milk-pt-all", "path tracer"), ("cube-milk-pt-single", "single only"),
             ("cube-milk-taulut-25", "taulut 25^3"), ("cube-milk-taulut-60", "taulut 60^3"),
             ("cube-milk-single", "voxel-single")],
    "bottle": [("bottle-wine-pt-all", "path tracer"), ("bottle-wine-taulut-60", "taulut 60^3"),
               ("bottle-tsm", "tsm (no wine)"), ("bottle-wine-pt-single", "single only"),
               ("bottle-wine-single", "voxel-single")],
}
for name, tiles in rows.items():
    images = [Image.open(f"{out}/{t}.png").convert("RGB") for t, _ in tiles]
    w, h = images[0].size
    sheet = Image.new("RGB", (w * len(images), h + 18), "white")
    draw = ImageDraw.Draw(sheet)
    for i, (img, (_, label)) in enumerate(zip(images, tiles)):
        sheet.paste(img, (i * w, 18))
        draw.text((i * w + 4, 3), label, fill="black")
    sheet.save(f"{out}/montage-{name}.png")
EOF
