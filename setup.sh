#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine:
#   ./setup.sh demo   install what is missing, build, run the main job on an embedded sample
#   ./setup.sh test   install what is missing, build, run the whole test suite
# Idempotent: packages already installed are not touched, and an up-to-date build does nothing.
set -euo pipefail
cd "$(dirname "$0")"

BUILD_DIR=${HULLPACK_BUILD_DIR:-build}
JOBS=$(nproc 2>/dev/null || echo 2)

# Debian packages the build and the tests need (keep sorted).
PACKAGES=(
  chromium
  clang
  clang-format
  cmake
  emscripten
  g++
  ignition-tools
  libassimp-dev
  libbullet-dev
  libbullet-extras-dev
  libclang-rt-14-dev
  libdraco-dev
  libeigen3-dev
  libgmock-dev
  libgtest-dev
  libmeshoptimizer-dev
  libsdformat-dev
  liburdfdom-tools
  make
  munge
  ninja-build
  nlohmann-json3-dev
  node-acorn
  nodejs
  npm
  pkg-config
  pybind11-dev
  python3-dev
  python3-numpy
  python3-pybind11
  python3-setuptools
  slurm-wlm
  zlib1g-dev
)

# Each line carries the seconds since the start, so a CI log shows what each stage took.
log() { printf 'setup [%ds]: %s\n' "$SECONDS" "$*" >&2; }

install_missing_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    # NodeSource's nodejs package bundles npm (and conflicts with Debian's npm package).
    [ "$p" = npm ] && command -v npm >/dev/null && continue
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { log "need root or sudo to install: ${missing[*]}"; exit 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# Node packages pinned in package-lock.json (the glTF-Validator used by tests/tools/gltf; three and
# playwright-core for web/ and tests/web). Re-run when package-lock.json is newer than the install.
install_node_packages() {
  [ node_modules/.package-lock.json -nt package-lock.json ] && return 0
  command -v npm >/dev/null || { log "npm not found; the glTF-Validator test will be skipped"; return 0; }
  log "installing node packages (npm ci)"
  npm ci --no-audit --no-fund || log "npm ci failed; the glTF-Validator test will be skipped"
}

configure_and_build() {
  if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    log "configuring $BUILD_DIR"
    cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
  fi
  log "building ($JOBS jobs)"
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

# WebAssembly decoder + viewer sample (web/, samples/web/dist), only when emscripten is there.
build_web() {
  command -v emcc >/dev/null || { log "emcc not found; skipping the WebAssembly decoder (web/)"; return 0; }
  log "building the WebAssembly decoder (web/ -> samples/web/dist)"
  bash web/build_wasm.sh "$BUILD_DIR/web-wasm" >/dev/null || { log "WebAssembly build failed"; return 0; }
  # The sample page's assets, made by `hullpack pack`: the torus and a generated mug.
  local hullpack="$BUILD_DIR/tools/hullpack/hullpack"
  if [ -x "$hullpack" ] && command -v node >/dev/null; then
    { "$hullpack" pack samples/torus.obj -o samples/web/dist/torus.glb --force --quiet &&
      node samples/web/make_mug.mjs samples/web/dist/mug.obj &&
      "$hullpack" pack samples/web/dist/mug.obj -o samples/web/dist/mug.glb --force --quiet; } >&2 ||
      log "could not make the sample page's packed assets (samples/web/dist)"
  fi
}

# One clang ASan+UBSan tree (-DHULLPACK_FUZZ=ON, -O2) serves the sanitized test suite and the
# libFuzzer targets: the libraries the fuzzers reach also get coverage hooks (tools/fuzz/), only the
# fuzzers link libFuzzer, and the benchmark programs are left out. One tree instead of two keeps
# .ci/run within its time budget; -O2 because the tests run several times faster than at -O1 (clang
# leaves Eigen's small functions out of line there) for a little more compile time.
SANITIZE_DIR=${HULLPACK_SANITIZE_BUILD_DIR:-$BUILD_DIR-sanitize}

configure_sanitized() {
  # A tree configured otherwise (gcc, or without the fuzzers) is configured afresh.
  if [ -f "$SANITIZE_DIR/CMakeCache.txt" ] && ! grep -q '^HULLPACK_FUZZ:BOOL=ON' "$SANITIZE_DIR/CMakeCache.txt"; then
    rm -rf "$SANITIZE_DIR/CMakeCache.txt" "$SANITIZE_DIR/CMakeFiles"
  fi
  if [ ! -f "$SANITIZE_DIR/CMakeCache.txt" ]; then
    log "configuring $SANITIZE_DIR (clang, ASan+UBSan, -O2: the tests and the fuzzers)"
    CC=clang CXX=clang++ cmake -S . -B "$SANITIZE_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHULLPACK_FUZZ=ON \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" >/dev/null
  fi
}

# The whole ctest suite again in the sanitized tree (-fno-sanitize-recover: any report fails its
# test; LeakSanitizer on, with tests/sanitizers/lsan.supp for third-party leaks). Leaves out the
# "heavy" label (the 2-million-triangle stability case: the plain run covers it, and it takes many
# minutes under ASan) and web_browser (the WebAssembly decoder in Chromium, which no sanitizer sees;
# the plain run covers it). The one-node Slurm cluster test (hullpack_batch_slurm, label "daemon") is
# registered in the plain tree only. HULLPACK_SANITIZE_TESTS=0 skips the stage. Freed memory stays
# poisoned until 64 MB more is freed: with ASan's default, 256 MB, a test's process grew by that
# much before reusing any, and faulting in the fresh pages took a fifth of the stage's time.
sanitized_tests() {
  [ "${HULLPACK_SANITIZE_TESTS:-1}" = 0 ] && return 0
  log "building the sanitized tests ($JOBS jobs)"
  cmake --build "$SANITIZE_DIR" -j "$JOBS"
  log "running the sanitized tests ($JOBS jobs)"
  ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_string_checks=1:quarantine_size_mb=64 \
    LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0" \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$SANITIZE_DIR" --output-on-failure -j "$JOBS" -LE heavy -E '^web_browser$'
}

case "${1:-}" in
  demo)
    install_missing_packages
    configure_and_build
    # The main job on the embedded sample: compressed mesh + convex collision hulls in one GLB.
    out="$BUILD_DIR/demo"
    mkdir -p "$out"
    log "running: hullpack pack samples/torus.obj -o $out/torus.packed.glb --report $out/torus.report.json --force"
    "$BUILD_DIR/tools/hullpack/hullpack" pack samples/torus.obj -o "$out/torus.packed.glb" \
      --report "$out/torus.report.json" --force
    "$BUILD_DIR/tools/hullpack/hullpack" info "$out/torus.packed.glb"
    ;;
  test)
    install_missing_packages
    install_node_packages
    configure_and_build
    build_web
    log "running the tests ($JOBS jobs)"
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
    if [ "${HULLPACK_SANITIZE_TESTS:-1}" != 0 ] || [ "${HULLPACK_FUZZ_SECONDS:-60}" != 0 ]; then
      configure_sanitized
    fi
    sanitized_tests
    # A short libFuzzer run of every decoder and parser from the same tree: HULLPACK_FUZZ_SECONDS
    # per target (0 skips it).
    if [ "${HULLPACK_FUZZ_SECONDS:-60}" != 0 ]; then
      log "fuzzing every decoder and parser for ${HULLPACK_FUZZ_SECONDS:-60} s each"
      HULLPACK_FUZZ_BUILD_DIR=$SANITIZE_DIR tests/fuzz/run_fuzzers.sh "${HULLPACK_FUZZ_SECONDS:-60}"
    fi
    log "all tests passed"
    ;;
  -h | --help)
    sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'
    ;;
  *)
    echo "setup.sh: unknown command '${1:-}' (usage: ./setup.sh demo|test; see --help)" >&2
    exit 64
    ;;
esac
