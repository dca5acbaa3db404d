#!/usr/bin/env bash
# Installs, builds and runs the main job: the fleet demo scene on an
# irregular sea with wind (models/jonswap.xml), then renders a short clip of
# it (docs/tools.md, mjbuoy-sim --render).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${MJBUOY_BUILD:-build}
mkdir -p out
"$build/tools/mjbuoy-sim" models/jonswap.xml --duration "${DURATION:-30}" --csv out/fleet.csv \
  --plot out/fleet_motion.png
# the clip: headless (EGL), MuJoCo's renderer plus the moving sea, H.264 via ffmpeg
"$build/tools/mjbuoy-sim" models/jonswap.xml --duration "${CLIP_SECONDS:-6}" \
  --render out/fleet.mp4 --width 960 --height 540 --fps 30 >/dev/null
echo "demo: wrote the clip $(pwd)/out/fleet.mp4 (${CLIP_SECONDS:-6} s, 960x540, 30 fps)" \
  "and the motion plot $(pwd)/out/fleet_motion.png"
