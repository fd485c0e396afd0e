#!/usr/bin/env bash
# libFuzzer (clang) on lucent's input paths: mesh files (.obj, .ply, .stl, .off), the EXR environment reader,
# the .vti and .vdb density readers, every scan format --volume reads (.nrrd, .mha, .nii, .nii.gz, .vtk, a
# DICOM folder), the CLI's arguments. Builds the targets in the sanitizer tree (build-sanitize/, ASan +
# UBSan, coverage on the input readers), runs each for LUCENT_FUZZ_SECONDS (default 10, keeping CI's test
# command within 45 minutes; run longer by hand) from the seed corpus in fuzz/corpus/, and fails on any
# finding (the input is kept in build-sanitize/fuzz-findings/: copy it into fuzz/corpus/TARGET/ as a
# regression input).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/lib/sanitize-tree.sh
tree=build-sanitize
targets=(fuzz_mesh_obj fuzz_mesh_ply fuzz_mesh_stl fuzz_mesh_off fuzz_exr fuzz_volume fuzz_volume_vdb
  fuzz_scan_nrrd fuzz_scan_mha fuzz_scan_nii fuzz_scan_nii_gz fuzz_scan_vtk fuzz_scan_dicom fuzz_cli_args)
cmake --build "$tree" -j"$(nproc)" --target "${targets[@]}"
seconds=${LUCENT_FUZZ_SECONDS:-10}
mkdir -p "$tree/fuzz-findings"
export ASAN_OPTIONS="detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
for t in "${targets[@]}"; do
  seeds=fuzz/corpus/${t#fuzz_}
  mkdir -p "$tree/fuzz-corpus/$t"

  rc=0
  # OpenVDB's tree reader allocates a compressed block's declared size before reading it
  # (bloscFromStream): outside ASan a corrupt size is an exception lucent turns into exit 2
  # (tests/data/vdb, test_vdb_io.cpp), under ASan a reported allocation within seconds of mutating.
  # So CI runs the .vdb corpus (seeds and past findings) without mutating; LUCENT_FUZZ_VDB=1 mutates.
  limit=(-max_total_time="$seconds")
  [ "$t" = fuzz_volume_vdb ] && [ "${LUCENT_FUZZ_VDB:-0}" != 1 ] && limit=(-runs=0)
  echo "lucent fuzz: $t ${limit[0]#-} (seeds: $seeds)"
  "$tree/fuzz/$t" "${limit[@]}" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$tree/fuzz-findings/$t-" "$tree/fuzz-corpus/$t" "$seeds" > "$tree/fuzz/$t.log" 2>&1 || rc=$?
  grep -E "^(stat::number_of_executed_units|stat::new_units_added|==[0-9]+==ERROR|SUMMARY)" "$tree/fuzz/$t.log" || true
  if [ "$rc" -ne 0 ]; then
    tail -40 "$tree/fuzz/$t.log"
    echo "lucent fuzz: $t found a problem (exit $rc); the input is in $tree/fuzz-findings/" >&2
    exit 1
  fi
done
echo "lucent fuzz: clean"
