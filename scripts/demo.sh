#!/usr/bin/env bash
# Installs, builds and runs the main job: the fleet demo scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${MJBUOY_BUILD:-build}
mkdir -p out
"$build/tools/mjbuoy-sim" models/fleet.xml --duration "${DURATION:-30}" --csv out/fleet.csv
