#!/usr/bin/env bash
# Installs, builds and runs every test with CTest (docs/testing.md), in
# three phases:
#   release   the Release build in build/ (scripts/setup.sh), its suite
#   sanitize  the same suite built with ASan + UBSan in build-asan/
#             (-DMJBUOY_SANITIZE=ON)
#   fuzz      the libFuzzer targets (clang) in build-fuzz/, each for
#             MJBUOY_FUZZ_SECONDS (60) on a copy of its seed corpus
# All three run by default; --no-release, --no-sanitize, --no-fuzz skip one
# (e.g. `bash scripts/test.sh --no-sanitize --no-fuzz` for quick local
# work). Other arguments go to the release and sanitize ctest runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build=${MJBUOY_BUILD:-build}
asan=${MJBUOY_ASAN_BUILD:-build-asan}
fuzz=${MJBUOY_FUZZ_BUILD:-build-fuzz}
jobs=$(nproc)

run_release=1 run_sanitize=1 run_fuzz=1
args=()
for a in "$@"; do
  case $a in
    --no-release) run_release=0 ;;
    --no-sanitize) run_sanitize=0 ;;
    --no-fuzz) run_fuzz=0 ;;
    *) args+=("$a") ;;
  esac
done

# the 600 s soak runs (label soak, docs/testing.md "Long tests") and the converged
# panel-solver validation (label panel) only when a label is asked for,
# e.g. bash scripts/test.sh -L soak
exclude=(-LE 'soak|panel')
for a in "${args[@]+"${args[@]}"}"; do
  case $a in
    -LE* | --label-exclude*) ;;
    -L* | --label-regex*) exclude=() ;;
  esac
done

# phase timing: "name seconds" lines, printed at the end
times=()
status=0
phase() {  # phase NAME COMMAND...: run, time, remember a failure
  local name=$1 t0=$SECONDS
  shift
  echo "== test.sh: $name"
  if "$@"; then
    times+=("$name $((SECONDS - t0)) s")
  else
    times+=("$name $((SECONDS - t0)) s FAILED")
    status=1
  fi
}

if [ $run_release = 1 ]; then
  phase "release tests" ctest --test-dir "$build" --output-on-failure -j"$jobs" \
    "${exclude[@]+"${exclude[@]}"}" "${args[@]+"${args[@]}"}"
fi

if [ $run_sanitize = 1 ]; then
  # one radiation cache for both phases (docs/testing.md "Radiation
  # cache"): the panel solutions the release tests computed are read by
  # the sanitize tests (their keys are the same bits: no fast-math, same
  # SSE2 code), so ASan runs no panel solve the release phase already ran
  radcache=$(sed -n 's/^MJBUOY_TEST_RADCACHE:PATH=//p' "$build/CMakeCache.txt" 2>/dev/null)
  radcache=${radcache:-$(realpath -m "$build/radcache")}
  sanitize_build() {
    cmake -S . -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMJBUOY_SANITIZE=ON \
      -DMJBUOY_TEST_RADCACHE="$radcache" >/dev/null &&
      cmake --build "$asan" -j"$jobs" 2>&1 | { grep -E "error|Error" || true; } &&
      test -x "$asan/tools/mjbuoy-sim"
  }
  phase "sanitize build" sanitize_build
  # long physics runs are shortened in this build (MJBUOY_SANITIZE in
  # tests/CMakeLists.txt); timeouts stay those of the Release suite
  # the 7744-triangle cases (label release-only, tests/CMakeLists.txt) ran
  # in the release phase; the 2800-triangle ones take their code paths here
  asan_exclude=(-LE 'soak|panel|release-only')
  # long simulations whose code paths shorter cases reach under the
  # sanitizers (docs/testing.md "Sanitizers"): the drag-exponent turning
  # circles (TriVec's exponent cases), the ramp's 60 s drift runs
  # (Ramp.BackendsSeeTheRampedAmplitude), the fleet scenario
  # (Models.FleetRidesTheWaves) and the two JONSWAP Wigley scenarios
  # (soak.W64_JONSWAP_long, TriVec's JONSWAP cases); they run in the
  # release phase
  asan_long='^(Hydro\.TurningRadiusShrinksWithLowerDragExponents|Ramp\.(DefaultRampLeavesADownwaveDrift|StartUpDriftIsTheLinearTransientAndTheRampRemovesIt)|scenario\.(fleet|wigley_256_jonswap_tp[0-9]+))$'
  asan_exclude+=(-E "$asan_long")
  [ ${#exclude[@]} = 0 ] && asan_exclude=()
  phase "sanitize tests" ctest --test-dir "$asan" --output-on-failure -j"$jobs" \
    "${asan_exclude[@]+"${asan_exclude[@]}"}" "${args[@]+"${args[@]}"}"
fi

if [ $run_fuzz = 1 ]; then
  fuzz_build() {
    CC=clang CXX=clang++ cmake -S . -B "$fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DMJBUOY_FUZZ=ON >/dev/null &&
      cmake --build "$fuzz" -j"$jobs" --target fuzz_kernel fuzz_config fuzz_setsea fuzz_scenario fuzz_gl 2>&1 |
      { grep -E "error|Error" || true; } &&
      test -x "$fuzz/tests/fuzz/fuzz_kernel"
  }
  phase "fuzz build" fuzz_build
  # the five targets four at a time, each for MJBUOY_FUZZ_SECONDS (CMake
  # cache, 60): two minutes of wall time whatever the core count
  phase "fuzz runs" ctest --test-dir "$fuzz" --output-on-failure -j4 -L fuzz
fi

echo "== test.sh: phase times"
printf '  %s\n' "${times[@]}"
exit $status
