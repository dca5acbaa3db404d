#!/usr/bin/env bash
# Installs, builds and runs every test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${MJBUOY_BUILD:-build}
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
