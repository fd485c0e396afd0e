#!/usr/bin/env bash
# The unit and integration tests (and the CLI they run) built with AddressSanitizer + UndefinedBehaviorSanitizer
# in build-asan/, and run: any report fails the run. Part of scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build-asan/CMakeCache.txt ] ||
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLUCENT_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$(nproc)" --target lucent lucent_unit_tests lucent_integration_tests
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
build-asan/tests/lucent_unit_tests
# Two accuracy sweeps are left to the Release run (ctest), which checks their numbers: every profile of
# every technique, and prt against thousands of path-traced paths. Their code runs here in the smaller
# tests (the profiles in the unit tests, every technique in the hard-case matrix and the frame-knob test,
# prt and its specular term in test_prt.cpp and the frame-knob test); under ASan they took minutes.
build-asan/tests/lucent_integration_tests \
  -tce="Every technique that takes a profile renders every profile*,prt against the path tracer*"
echo "lucent sanitizers: clean"
