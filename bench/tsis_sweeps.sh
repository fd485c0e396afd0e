#!/usr/bin/env bash
# The accuracy-cost sweeps of texture-space-importance-sampling, in the paper's structure, against the
# brute-force dipole truth (fraction 0.5 of the mean free path), with Jensen-Buhler as the baseline
# curve for speed-ups at equal error. Writes CSV + PNG into docs/accuracy/tsis/. ~10 min on 2 cores.
# Usage: bench/tsis_sweeps.sh [build-dir]
set -euo pipefail
build=${1:-build}
out=docs/accuracy/tsis
mkdir -p "$out"
lucent="$build/lucent"
ref=(--reference-knob fraction=0.5 --quiet)
jb=(--baseline-method jensen-buhler --baseline-sweep epsilon=3,1,0.3,0.1,0.03)
samples=49,100,169,256,400,900,1600,2500

# Tables 2-3 and Fig. 7: time and error against samples, per pixel and per vertex, 10/20/30 mm.
for shape in sphere genus7; do
  for size in 10 20 30; do
    for material in skin1 skin2; do
      name="$shape-$size-$material"
      echo "== $name"
      "$lucent" bench --shape "$shape" --size-mm "$size" --material "$material" --method tsis \
        --sweep samples=$samples --sweep eval=pixel,vertex "${ref[@]}" "${jb[@]}" \
        --csv "$out/samples-$name.csv" --plot "$out/samples-$name.png" --plot-x samples > "$out/samples-$name.txt"
    done
  done
done

# Fig. 13-14: at 30 mm TSIS needs ever more samples as the mean free path shrinks; hybrid 900 + 401.
for material in skin1 marble cream; do
  name="sphere-30-$material"
  echo "== $name"
  "$lucent" bench --shape sphere --size-mm 30 --material "$material" --method tsis \
    --sweep samples=900,3600,14400,62500 "${ref[@]}" "${jb[@]}" \
    --csv "$out/fig13-tsis-$name.csv" --plot "$out/fig13-tsis-$name.png" > "$out/fig13-tsis-$name.txt"
  "$lucent" bench --shape sphere --size-mm 30 --material "$material" --method hybrid \
    --sweep samples=900 --sweep c=0.2,0.1,0.05,0.02 "${ref[@]}" "${jb[@]}" \
    --csv "$out/fig13-hybrid-$name.csv" --plot "$out/fig13-hybrid-$name.png" > "$out/fig13-hybrid-$name.txt"
done

# The default scene (genus-7 ring, 30 mm, skin1): every method's knobs against the same truth.
echo "== default scene"
"$lucent" bench --method tsis --sweep samples=400,1600,6400,25600 --sweep atlas-resolution=512,1024 "${ref[@]}" "${jb[@]}" \
  --csv "$out/default-tsis.csv" --plot "$out/default-tsis.png" > "$out/default-tsis.txt"
"$lucent" bench --method hybrid --sweep samples=400,900,3600 --sweep rings=10,20 "${ref[@]}" "${jb[@]}" \
  --csv "$out/default-hybrid.csv" --plot "$out/default-hybrid.png" > "$out/default-hybrid.txt"
"$lucent" bench --method tsm --sweep rings=5,10,20,40 --sweep map=256,512,1024 "${ref[@]}" "${jb[@]}" \
  --csv "$out/default-tsm.csv" --plot "$out/default-tsm.png" > "$out/default-tsm.txt"
"$lucent" bench --method tsis --sweep sampler=mip,row --sweep pattern=stratified,independent --knob samples=1600 \
  "${ref[@]}" --csv "$out/default-sampler.csv" > "$out/default-sampler.txt"
echo "written to $out"
