#!/usr/bin/env bash
# One entry point for setting up, building and running Fractograph on Debian 12.
#   bash scripts/fractograph.sh demo   install, build, compile a gallery graph, render a stereo frame
#   bash scripts/fractograph.sh test   install, build, run every test; again under ASan + UBSan; each
#                                      fuzzer for a minute (scripts/fuzz.sh SECONDS for long runs)
#   bash scripts/fractograph.sh build  install and build the tools only (no tests)
#   bash scripts/fractograph.sh bench  install what the benchmark scripts need too, and build (bench/)
#   bash scripts/fractograph.sh packages demo|test|bench   the Debian packages that command installs
# Idempotent: packages already installed are not touched, and a built tree only rebuilds what changed.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${FG_BUILD_DIR:-$ROOT/build}
JOBS=${FG_JOBS:-$(nproc)}

BUILD_PACKAGES=(build-essential cmake ninja-build pkg-config ccache)
LIB_PACKAGES=(glslang-dev glslang-tools spirv-tools libspirv-cross-c-shared-dev spirv-cross libvulkan-dev
  mesa-vulkan-drivers vulkan-tools vulkan-validationlayers libglm-dev nlohmann-json3-dev libopenxr-dev
  libopenxr-loader1 libopenxr-utils openxr-layer-corevalidation libglfw3-dev libstb-dev libcli11-dev libfmt-dev
  libspdlog-dev libxxhash-dev libpng-dev libcpp-httplib-dev libopenexr-dev libopenvdb-dev libtbb-dev
  libboost-dev)  # OpenVDB's headers include Boost's, but Debian 12's libopenvdb-dev does not depend on it
TEST_PACKAGES=(libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth python3-matplotlib python3-jsonschema clang
  libclang-rt-14-dev chromium slurm-wlm munge python3-openvdb python3-vtk9 admesh time)
# The benchmark scripts' picture scores (SSIM) and plots, beyond the tests' packages.
BENCH_PACKAGES=(python3-skimage python3-matplotlib)

# Node.js and npm for the studio's page, when the machine has no npm of its own.
STUDIO_PACKAGES=(nodejs npm)

# The packages a command installs, one a line (scripts/check_packages.py checks the build against them).
packages_of() {
  case "$1" in
    demo|build) printf '%s\n' "${BUILD_PACKAGES[@]}" "${LIB_PACKAGES[@]}" "${STUDIO_PACKAGES[@]}" ;;
    test) printf '%s\n' "${BUILD_PACKAGES[@]}" "${LIB_PACKAGES[@]}" "${STUDIO_PACKAGES[@]}" "${TEST_PACKAGES[@]}" ;;
    bench) packages_of test; printf '%s\n' "${BENCH_PACKAGES[@]}" ;;
    *) echo "packages of demo, test or bench, not '$1'" >&2; exit 2 ;;
  esac
}

say() { printf '\033[1m==> %s\033[0m\n' "$*"; }

install_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  say "installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# The studio's page (studio/): Node.js and npm from the machine (Debian's when missing), and the
# exact packages of package-lock.json; the build embeds the page, so nothing is fetched at run time.
studio_packages() {
  if ! command -v npm >/dev/null 2>&1; then install_packages "${STUDIO_PACKAGES[@]}"; fi
  if [ ! -d "$ROOT/studio/node_modules" ] || [ "$ROOT/studio/package-lock.json" -nt "$ROOT/studio/node_modules/.package-lock.json" ]; then
    say "installing the studio page's npm packages (npm ci)"
    (cd "$ROOT/studio" && npm ci --no-audit --no-fund --loglevel=error)
  fi
}

# build [tests]: the tools; with "tests", the tests and benchmark programs too. The demo configures
# without them, so it needs none of the test packages; a tree configured for tests stays so.
build() {
  studio_packages
  local with_tests=OFF
  [ "${1:-}" = tests ] && with_tests=ON
  if [ ! -f "$BUILD/build.ninja" ] || { [ $with_tests = ON ] && grep -q '^FG_BUILD_TESTS:BOOL=OFF' "$BUILD/CMakeCache.txt"; }; then
    say "configuring $BUILD"
    # -g1: line tables name file and line in backtraces and profiles; full -g costs a fifth more build time.
    # shellcheck disable=SC2046
    cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
      -DFG_BUILD_TESTS=$with_tests -DFG_BUILD_BENCH=$with_tests $(launcher) >/dev/null
  fi
  say "building (log: $BUILD/build.log)"
  run_logged "$BUILD/build.log" cmake --build "$BUILD" -j "$JOBS"
}

# Run a command with its output in a log; show progress every 50 steps and the log's end on failure.
run_logged() {
  local log=$1; shift
  set +e
  "$@" >"$log" 2>&1 &
  local pid=$! last=""
  while kill -0 "$pid" 2>/dev/null; do
    sleep 5
    local now
    now=$(grep -o -E '^\[[0-9]+/[0-9]+\]' "$log" | tail -1)
    [ -n "$now" ] && [ "$now" != "$last" ] && { echo "    $now"; last=$now; }
  done
  wait "$pid"
  local rc=$?
  set -e
  if [ $rc -ne 0 ]; then tail -60 "$log"; echo "failed: $*"; exit 1; fi
}

# ccache keeps compiled objects between builds of any clone (paths under the clone are hashed
# relative to it), so a fresh clone on a machine that built before recompiles only what changed.
export CCACHE_BASEDIR=$ROOT CCACHE_NOHASHDIR=1
launcher() { command -v ccache >/dev/null && echo "-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; true; }

# Headless runs use Mesa's lavapipe; keep its shader cache out of the home folder.
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$BUILD/mesa-cache}

demo() {
  install_packages "${BUILD_PACKAGES[@]}" "${LIB_PACKAGES[@]}"
  build
  local out=$ROOT/out/demo
  mkdir -p "$out"
  say "compiling graphs/gallery/mandelbulb.json"
  "$BUILD/compiler/fgc" compile "$ROOT/graphs/gallery/mandelbulb.json" -o "$out/mandelbulb.fgpack"
  if [ -x "$BUILD/runtime/fgplay" ]; then
    say "rendering a stereo frame headless on lavapipe"
    "$BUILD/runtime/fgplay" render "$out/mandelbulb.fgpack" --out "$out" --size 512x512
    say "images: $out/left.png $out/right.png $out/side_by_side.png"
  fi
}

# The fuzzers for a minute each (scripts/fuzz.sh; run it alone for long runs).
run_fuzzers() {
  say "building and running the fuzzers for ${FG_FUZZ_SECONDS:-60}s each"
  bash "$ROOT/scripts/fuzz.sh" "${FG_FUZZ_SECONDS:-60}"
}

# The project again with AddressSanitizer and UndefinedBehaviorSanitizer (gcc, FG_SANITIZE=ON, in
# $BUILD-sanitize, no benchmark programs; -O1 -g1 builds in about half the time of -O2 -g and still
# names file and line) and the tests under them. Left out (docs/testing.md): the gallery's frame
# hashes (the same passes run in the other runtime tests), the studio in Chromium and the Slurm
# cluster (a browser and daemons, not our code), the 8K EXR memory bound (it bounds the plain
# build; ASan doubles the heap), fgplay's benchmark sweep (5 min under ASan) and its quick headset
# sequence (222 s; the timed sequence test runs its code on one trace under ASan), every truncation of
# a pack (90 s; the pack reader's fuzzer covers it under ASan), the 2048x2056 eye whose tile list
# takes two dispatch rows (58 s; its host code is the other FoveatedTiles tests', its rows the GPU's)
# and the same for frames against whole-image dispatches (39 s), and compiling the whole gallery in
# float and in double (85 s and 44 s, mostly glslang and spirv-val under ASan's allocator; the other
# compile tests and the compiler's fuzzer run our compiler under ASan), the installed form and the
# .deb (a packaging check: an instrumented .deb is not what users get), and the export's closed-form
# meshes (millions of triangles at the default resolution; the gallery and shard export tests run
# the same sampler, mesher and writers under ASan on smaller meshes), the hard cases' NaN sweeps
# (54 runs of one host path, 358 s; what they check is the GPU's arithmetic, and the calibrated
# hard cases run that host path under ASan) and each library node compiled alone (83 runs of one
# compile path, 340 s, mostly glslang; every node's CPU twin and tangent rule, the compile tests
# and fuzz_compiler run under ASan).
SANITIZE_SKIP='^install\.|^FrameHashes\.|^studio\.browser|^slurm\.|^ExrOutput\.an_8k|^fgplay\.renders_refuses_bad_packs_and_benchmarks$|^fgplay\.bench_sequence_quick_reports_every_trace_and_setting$|^Pack\.every_truncation|^FoveatedTiles\.an_eye_of_more_tiles_than_a_dispatch_row|^FoveatedTiles\.frames_are_bit_identical_to_dispatches_over_the_whole_image$|^Compile\.every_gallery_graph_compiles|^DoublePrecision\.the_gallery_compiles_in_double|^export\.sphere_torus_and_sponge_meshes_match_their_closed_forms$|^stability\.(Cases|Formulas)/HardCase\.|^Library/NodeCompiles\.'
SANITIZE_BUILD=$BUILD-sanitize
build_sanitized() {
  local san=$SANITIZE_BUILD
  if [ ! -f "$san/build.ninja" ]; then
    # shellcheck disable=SC2046
    cmake -S "$ROOT" -B "$san" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DFG_SANITIZE=ON -DFG_BUILD_BENCH=OFF $(launcher) >/dev/null
  fi
  say "building with ASan + UBSan (log: $san/build.log)"
  run_logged "$san/build.log" cmake --build "$san" -j "$JOBS"
  # Not instrumented: it is preloaded into every process of the run, cmake and bash included.
  cc -shared -fPIC -O2 -o "$san/libkeep_layers_loaded.so" "$ROOT/tests/sanitizers/keep_layers_loaded.c"
}

sanitized_ctest() {
  local san=$SANITIZE_BUILD
  # Leaks inside Debian's validation layers and OpenXR loader are theirs (tests/sanitizers/lsan.supp).
  (cd "$san" && MESA_SHADER_CACHE_DIR=$san/mesa-cache LD_PRELOAD=$san/libkeep_layers_loaded.so \
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0:verify_asan_link_order=0 \
    LSAN_OPTIONS=suppressions=$ROOT/tests/sanitizers/lsan.supp:print_suppressions=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --output-on-failure -j "$JOBS" --timeout 1500 --output-junit "$san/ctest.xml" "$@")
}

run_sanitized_tests() {
  say "running the tests under ASan + UBSan"
  sanitized_ctest -E "$SANITIZE_SKIP" && return 0
  # LeakSanitizer's own stop-the-world tracer now and then crashes as a process exits ("Tracer
  # caught signal 11", a fault of the sanitizer runtime, not a leak). Tests that failed only that
  # way run once more; any other failure stands.
  python3 "$ROOT/scripts/lsan_tracer_crashes.py" "$SANITIZE_BUILD/ctest.xml" || return 1
  say "running again the tests that failed only by LeakSanitizer's tracer crash"
  sanitized_ctest --rerun-failed
}

run_tests() {
  say "running tests"
  (cd "$BUILD" && ctest --output-on-failure -j "$JOBS" --timeout 1500)
}

# `test` times each stage against a budget in minutes (measured on 2 cores with the packages
# installed and ccache holding the objects of an earlier build, plus a margin; they add up to 45),
# so a stage that grows says so in the log long before the whole run nears CI's 90-minute limit.
STAGE_TIMES=()
stage() {
  local name=$1 budget=$2 start=$SECONDS
  shift 2
  "$@"
  local took=$((SECONDS - start))
  STAGE_TIMES+=("$(awk -v n="$name" -v t="$took" -v b="$budget" 'BEGIN { printf "  %-22s %5.1f min  (budget %d)", n, t / 60, b }')")
  say "stage '$name' took $(awk -v t="$took" 'BEGIN { printf "%.1f", t / 60 }') min (budget $budget)"
  if [ "$took" -gt $((budget * 60)) ]; then
    printf '\033[1;33mwarning: stage %s took %d min %d s, over its budget of %d min: find what grew (docs/testing.md)\033[0m\n' \
      "$name" $((took / 60)) $((took % 60)) "$budget"
  fi
}

test_all() {
  local start=$SECONDS
  stage "install packages" 2 install_packages "${BUILD_PACKAGES[@]}" "${LIB_PACKAGES[@]}" "${TEST_PACKAGES[@]}"
  stage "build" 6 build tests
  stage "tests" 14 run_tests
  stage "sanitizer build" 5 build_sanitized
  stage "sanitizer tests" 16 run_sanitized_tests
  stage "fuzzers" 2 run_fuzzers
  say "all tests passed in $(((SECONDS - start) / 60)) min (budget 45):"
  printf '%s\n' "${STAGE_TIMES[@]}"
}

case "${1:-}" in
  demo) demo ;;
  test) test_all ;;
  build) install_packages "${BUILD_PACKAGES[@]}" "${LIB_PACKAGES[@]}"; build ;;
  bench) install_packages "${BUILD_PACKAGES[@]}" "${LIB_PACKAGES[@]}" "${TEST_PACKAGES[@]}" "${BENCH_PACKAGES[@]}"; build tests ;;
  packages) packages_of "${2:-test}" ;;
  *) echo "usage: $0 demo|test|build|bench|packages [demo|test|bench]" >&2; exit 2 ;;
esac
