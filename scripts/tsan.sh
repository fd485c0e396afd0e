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
# exitcode=0: a report must not change the CLI's exit code, which the tests check; reports are
# counted from the log instead.
export TSAN_OPTIONS="halt_on_error=0:exitcode=0:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp:log_path=$PWD/build-tsan/report"
rm -f build-tsan/report.*
rc=0
build-tsan/tests/lucent_unit_tests || rc=$?
build-tsan/tests/lucent_integration_tests "$@" || rc=$?
reports=$(cat build-tsan/report.* 2>/dev/null | grep -c "WARNING: ThreadSanitizer" || true)
echo "lucent tsan: tests exit $rc, $reports reports (build-tsan/report.*)"
[ "$rc" -eq 0 ] && [ "$reports" -eq 0 ]
