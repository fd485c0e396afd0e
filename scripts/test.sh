#!/usr/bin/env bash
# README command 2: install what is missing, build, run every test; the sanitizer and fuzzing stages; then the
# ParaView plugin's build and pvbatch tests (a build tree of its own, against ParaView's VTK).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/lib/apt-install-missing.sh chromium   # the report page's browser test (tests/report/)
scripts/build.sh
scripts/corpus.sh        # the real-data corpus (.corpus/, from Debian packages) that the realdata tests read
(cd build && ctest --output-on-failure -j"$(nproc)")
scripts/sanitize.sh      # the unit and integration tests under ASan + UBSan
scripts/fuzz.sh          # libFuzzer on the mesh, EXR, volume and argument readers, 20 s each
scripts/paraview-plugin.sh
