#!/usr/bin/env bash
# README command 2: install what is missing, build, run every test; the sanitizer and fuzzing stages; then the
# ParaView plugin's build and pvbatch tests (a build tree of its own, against ParaView's VTK).
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's wall time, on the terminal and in build/test-stages.log, so CI's 45-minute budget is
# watched stage by stage.
started=$SECONDS
stage() {
  local name=$1 begin=$SECONDS
  shift
  "$@"
  mkdir -p build
  echo "lucent test: ${name} took $((SECONDS - begin)) s (total $((SECONDS - started)) s)" |
    tee -a build/test-stages.log
}

stage "install" scripts/install-deps.sh
stage "chromium" scripts/lib/apt-install-missing.sh chromium   # the report page's browser test (tests/report/)
stage "build" scripts/build.sh
stage "corpus" scripts/corpus.sh   # the real-data corpus (.corpus/, from Debian packages) the realdata tests read
stage "ctest" bash -c 'cd build && ctest --output-on-failure -j"$(nproc)"'
stage "sanitize" scripts/sanitize.sh   # the unit and integration tests under ASan + UBSan
stage "fuzz" scripts/fuzz.sh           # libFuzzer on the mesh, EXR, volume, scan and argument readers, 10 s each
stage "paraview" scripts/paraview-plugin.sh
