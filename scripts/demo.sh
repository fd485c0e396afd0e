#!/usr/bin/env bash
# README command 1: install what is missing, build, render the built-in default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/lucent render --out out/demo.exr --out out/demo.png --stats out/demo.json
echo "lucent: wrote out/demo.exr, out/demo.png, out/demo.json"
