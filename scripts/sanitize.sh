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
build-asan/tests/lucent_integration_tests
echo "lucent sanitizers: clean"
