#!/usr/bin/env bash
# README command 2: install what is missing, build, run every test; then the ParaView plugin's build and
# pvbatch test (a build tree of its own, against ParaView's VTK; see scripts/paraview-plugin.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
scripts/paraview-plugin.sh
