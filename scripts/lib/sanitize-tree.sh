#!/usr/bin/env bash
# Configures build-sanitize/ (clang, ASan + UBSan, the libFuzzer targets) once: the tree that
# scripts/sanitize.sh tests and scripts/fuzz.sh fuzzes, so the libraries are compiled once for both.
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/lib/apt-install-missing.sh clang libclang-rt-14-dev
if ! grep -q "^LUCENT_FUZZ:BOOL=ON" build-sanitize/CMakeCache.txt 2>/dev/null; then
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DLUCENT_SANITIZE=ON -DLUCENT_FUZZ=ON >/dev/null
fi
