#!/usr/bin/env bash
# Installs, builds and runs every test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${MJBUOY_BUILD:-build}
# the 600 s soak runs (label soak, README "Long tests") only when a label is
# asked for, e.g. bash scripts/test.sh -L soak
exclude=(-LE soak)
for a in "$@"; do
  case $a in
    -LE* | --label-exclude*) ;;
    -L* | --label-regex*) exclude=() ;;
  esac
done
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "${exclude[@]}" "$@"
