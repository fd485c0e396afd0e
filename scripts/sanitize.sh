#!/usr/bin/env bash
# The unit and integration tests (and the CLI they run) built with AddressSanitizer + UndefinedBehaviorSanitizer
# in build-sanitize/ (clang), and run: any report fails the run. Part of scripts/test.sh.
#
# clang, not gcc: under the sanitizers at -O2 it compiles the core registry's unit in 73 s where gcc took
# 178 s (measured on src/technique/core_registry.cpp, this machine). scripts/fuzz.sh builds its targets
# in the same tree. Only the input readers carry libFuzzer's coverage instrumentation: with every
# library instrumented these tests ran 3.4 times longer (22 min against 6.5).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/lib/sanitize-tree.sh
cmake --build build-sanitize -j"$(nproc)" --target lucent lucent_unit_tests lucent_integration_tests
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Convergence sweeps are left to the Release run (ctest), which checks their numbers; their code runs here
# in smaller tests. Unit: path lengths at rising resolution (36 s under ASan; the LUT's code runs in the
# other taulut tests) and every profile's table for every material (15 s; the Rd table tests run the same
# code). Integration: every profile of every technique and prt against thousands of path-traced paths
# (minutes; the hard-case matrix and test_prt.cpp run that code), single scattering behind a Fresnel
# boundary under an environment (29 s; the index-matched and point-light single-scattering tests run it)
# and manifold next-event from an environment cap (15 s; four smaller manifold tests run it).
build-sanitize/tests/lucent_unit_tests \
  -tce="Path lengths between surface voxels converge*,Every profile's table meets the bound*"
build-sanitize/tests/lucent_integration_tests \
  -tce="Every technique that takes a profile renders every profile*,prt against the path tracer*,Single scattering behind a Fresnel boundary*,*manifold next-event estimation from directional lights spread over*"
echo "lucent sanitizers: clean"
