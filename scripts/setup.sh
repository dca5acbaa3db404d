#!/usr/bin/env bash
# Installs the Debian packages mjbuoy needs (idempotent: quiet when all are
# there), then configures and builds into build/. Why each package is here:
# docs/dependencies.md.
set -euo pipefail
cd "$(dirname "$0")/.."

pkgs=(
  cmake g++ make pkg-config
  libmujoco-dev libqhull-dev   # MuJoCo 2.2.2; its CMake config names qhull's include dir
  libc6-dev                    # libmvec: vector sin, cos, exp of the cpu backend (comes with g++)
  libeigen3-dev                # the panel solver's matrices (mjbuoy/radiation/panel.cc); small linear algebra in tests
  libopenblas-dev              # the panel solver's dense LU and products (mjbuoy/radiation/panellu.cc)
  libmeshoptimizer-dev         # quadric simplification of a hull too fine for the panel budget (mjbuoy/radiation/panelcoarse.cc)
  libhdf5-dev libnetcdf-dev    # coefficient files of other tools: BEMIO HDF5, Capytaine NetCDF (mjbuoy/radiation/coefio_*.cc)
  libgtest-dev                 # unit tests
  libcli11-dev                 # command-line parsing of the tools
  python3                      # CSV checks of the command-line tests
  libtinyxml2-dev              # XML parsing of mjbuoy-scenario (scenario files, model edits, JUnit) and mjb_checkModelFile
  libegl-dev libegl-mesa0      # headless EGL for the GL compute backend (Mesa's surfaceless platform)
  libgl1-mesa-dri              # Mesa's GL drivers (llvmpipe when there is no GPU)
  python3-glad                 # generates the GL loader at build time (/usr/bin/python3 -m glad)
  xvfb xauth                   # an X server for the test of GLX context restoring and the viewer tests
  libglfw3-dev                 # mjbuoy-view: window, compatibility GL context, input (GLFW 3)
  xdotool                      # the viewer tests: select, perturb and close the window through XTEST
  ffmpeg                       # mjbuoy-sim --render: encodes the clip (H.264 MP4); ffprobe for its test
  libpng-dev                   # mjbuoy-sim --snapshot: PNG stills
  gnuplot-nox                  # mjbuoy-sim --plot: heave, roll and pitch plots
  heaptrack                    # soak.fleet.3600s: records every allocation of the hour-long soak (tests/check_heaptrack.py)
  clang libclang-rt-14-dev     # libFuzzer (-fsanitize=fuzzer) for tests/fuzz, run by scripts/test.sh
  nlohmann-json3-dev           # mjbuoy-sweep: JSON result files (header-only)
  slurm-wlm munge              # mjbuoy-sweep slurm: sbatch; sweep.slurm starts a single-node Slurm (munged, slurmctld, slurmd)
  python3-dev pybind11-dev python3-pybind11 python3-numpy  # the Python module mjbuoy (python/, docs/python.md)
  python3-pytest python3-matplotlib  # its pytest suite; the plots of examples/python
  python3-sphinx python3-sphinx-rtd-theme python3-myst-parser  # the documentation site (docs/, target docs, tests docs.*)
)

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

build=${MJBUOY_BUILD:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
if [ "${MJBUOY_BUILD_PROGRESS:-0}" = 1 ]; then
  # scripts/demo.sh: a line per target built, with the percentage done
  cmake --build "$build" -j"$(nproc)" 2>&1 |
    grep --line-buffered -E "^\[ *[0-9]+%\] Built target|error|warning|Error" || true
else
  cmake --build "$build" -j"$(nproc)" 2>&1 | grep -E "error|warning|Error" || true
fi
test -x "$build/tools/mjbuoy-sim" || { echo "setup: build failed" >&2; exit 1; }
