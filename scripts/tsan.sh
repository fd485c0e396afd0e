#!/usr/bin/env bash
# ThreadSanitizer over the parallel paths: the unit and integration tests (the hard-case matrix runs
# every technique's parallel loops) built with -fsanitize=thread in build-tsan/. Debian's libtbb is
# not instrumented, so under TSan lucent's parallel loop runs on std::threads (src/util/tbb_parallel.hpp).
# Not part of CI (slow); results and how to read them: docs/reliability.md. Extra arguments go to the
# integration tests (e.g. -tc='Hard-case*').
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build-tsan/CMakeCache.txt ] ||
  cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLUCENT_TSAN=ON >/dev/null
cmake --build build-tsan -j"$(nproc)" --target lucent lucent_unit_tests lucent_integration_tests
export TSAN_OPTIONS="halt_on_error=0:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp"
rc=0
build-tsan/tests/lucent_unit_tests || rc=$?
build-tsan/tests/lucent_integration_tests "$@" || rc=$?
[ "$rc" -eq 0 ] && echo "lucent tsan: clean" || echo "lucent tsan: reports above (exit $rc)"
exit "$rc"
