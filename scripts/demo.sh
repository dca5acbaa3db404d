#!/usr/bin/env bash
# Installs, builds and runs the main job: the fleet demo scene on an
# irregular sea with wind (models/jonswap.xml), then renders a short clip of
# it (docs/tools.md, mjbuoy-sim --render). Every phase says what it does on
# stderr: the build a line per target, the panel solve at attach and the
# simulation's progress (mjbuoy-sim --progress).
set -euo pipefail
cd "$(dirname "$0")/.."
echo "demo: installing the packages and building (a line per target built)" >&2
MJBUOY_BUILD_PROGRESS=1 bash scripts/setup.sh
build=${MJBUOY_BUILD:-build}
mkdir -p out
# a bar on a terminal, else a line now and then
progress=lines
[ -t 2 ] && progress=bar
echo "demo: simulating ${DURATION:-30} s of models/jonswap.xml" >&2
"$build/tools/mjbuoy-sim" models/jonswap.xml --duration "${DURATION:-30}" --csv out/fleet.csv \
  --plot out/fleet_motion.png --progress "$progress"
# the clip: headless (EGL), MuJoCo's renderer plus the moving sea, H.264 via ffmpeg
echo "demo: rendering a ${CLIP_SECONDS:-6} s clip" >&2
"$build/tools/mjbuoy-sim" models/jonswap.xml --duration "${CLIP_SECONDS:-6}" \
  --render out/fleet.mp4 --width 960 --height 540 --fps 30 --progress lines >/dev/null
echo "demo: wrote the clip $(pwd)/out/fleet.mp4 (${CLIP_SECONDS:-6} s, 960x540, 30 fps)" \
  "and the motion plot $(pwd)/out/fleet_motion.png"
