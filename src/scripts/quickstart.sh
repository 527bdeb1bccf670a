#!/usr/bin/env bash
# Quick start for CGAL Subdiv on Debian 12 (bookworm); run from anywhere as root
# (or with sudo available):
#
#   bash src/scripts/quickstart.sh demo   # install what is missing, build cgal-subdiv, run its demo
#   bash src/scripts/quickstart.sh test   # install what is missing, build everything, run ctest
#   bash src/scripts/quickstart.sh deps   # only install what is missing
#
# Options (after the mode):
#   --with-peers      also install the optional peers (OpenMesh, OpenSubdiv; test
#                     mode installs OpenSubdiv in any case)
#   --jobs N          parallel build and test jobs (default: nproc; or set JOBS=N)
#   --no-sanitizers   test mode: skip the sanitizer job (build-asan/) and the
#                     fuzz job (build-fuzz/)
#
# The build is an optimised one that keeps CGAL's preconditions and assertions
# (Release with -O2, no NDEBUG) in build/ at the root of the checkout. Running it
# again only redoes what changed. In test mode the exit code is ctest's; before
# the tests, a subset of them runs under ASan + UBSan in build-asan/, and the
# fuzzers of src/fuzz/ run for a fixed time each (doc/ci.md).
set -euo pipefail

# libtbb-dev: optional for users of the library, installed here so that the
# tests run the multi-threaded paths (threads(n) runs in one thread without it);
# clang-format and git: the test format_check (src/scripts/check_format.sh);
# doxygen: the test doxygen (the reference manual builds without warnings)
readonly REQUIRED_PACKAGES=(cmake g++ make libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev
                            libgtest-dev libboost-dev libtbb-dev python3 clang-format git doxygen)

# Test mode (CI), doc/ci.md. -Wall -Wextra are always on for the project's own
# targets (tests, tools, examples, and so the headers they include); test mode
# adds -Werror (SUBDIV_WARNINGS_AS_ERRORS): a warning fails CI.
readonly WARNINGS_AS_ERRORS_IN_TEST=ON

# The sanitizer job of test mode: these targets built in build-asan/ with
# ASan + UBSan (-O1, assertions on), and the tests with these ctest labels
# (every GoogleTest executable is labelled with its name, the command-line
# tests with cli) run before the main tests. Measured on 2 cores, -j2 (doc/ci.md,
# which says why these): about N minutes more than the main build and tests.
readonly SANITIZER_TARGETS=(cgal-subdiv parallel_test stencil_table_test)
readonly SANITIZER_LABELS=(cli parallel_test stencil_table_test)
readonly PEER_PACKAGES=(libopenmesh-dev libosd-dev)
# Test mode installs OpenSubdiv whatever the options: the sharp-features suite
# compares every one of its regression shapes with OpenSubdiv Far in the same
# test, and fails (it never skips) where Far is missing
readonly TEST_PACKAGES=(libosd-dev)
# The fuzz job of test mode (with the sanitizer job): every libFuzzer target of
# src/fuzz/ built with clang and run for FUZZ_SECONDS each
# (src/scripts/fuzz.sh, doc/ci.md); clang's libFuzzer runtime is only a
# recommendation of clang, so it is named
readonly FUZZ_PACKAGES=(clang libclang-rt-14-dev)
readonly FUZZ_SECONDS=30

say() { printf '==> %s\n' "$*"; }
die() { printf 'quickstart: error: %s\n' "$*" >&2; exit 2; }

usage() {
  # the comment at the top of this file
  sed -n '2,/^set -euo pipefail$/p' "$0" | sed -n '/^#/s/^# \{0,1\}//p'
  exit "${1:-0}"
}

mode=${1:-}
[[ -n $mode ]] || usage 2
shift
case $mode in
  demo | test | deps) ;;
  -h | --help | help) usage 0 ;;
  *) printf 'quickstart: unknown mode "%s"\n\n' "$mode" >&2; usage 2 ;;
esac

with_peers=0
sanitizers=1
jobs=${JOBS:-}
while (($#)); do
  case $1 in
    --with-peers) with_peers=1 ;;
    --no-sanitizers) sanitizers=0 ;;
    --jobs) [[ $# -ge 2 ]] || die "--jobs needs a number"; jobs=$2; shift ;;
    --jobs=*) jobs=${1#--jobs=} ;;
    -h | --help) usage 0 ;;
    *) die "unknown option '$1' (try --help)" ;;
  esac
  shift
done
if [[ -z $jobs ]]; then
  jobs=$(nproc 2>/dev/null || echo 2)
fi
[[ $jobs =~ ^[1-9][0-9]*$ ]] || die "--jobs wants a positive number, got '$jobs'"

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$root/build
build_asan=$root/build-asan
cd "$root"

# --- dependencies ------------------------------------------------------------
is_installed() {
  [[ $(dpkg-query -W -f='${Status}' "$1" 2>/dev/null) == "install ok installed" ]]
}

install_missing() {
  local packages=("${REQUIRED_PACKAGES[@]}")
  ((with_peers)) && packages+=("${PEER_PACKAGES[@]}")
  if [[ $mode == test ]]; then
    packages+=("${TEST_PACKAGES[@]}")
    if ((sanitizers)); then
      packages+=("${FUZZ_PACKAGES[@]}")
    fi
  fi
  if ! command -v dpkg-query >/dev/null 2>&1; then
    say "not a Debian system: skipping package installation; make sure these (or their"
    say "equivalents) are installed: ${packages[*]}"
    return 0
  fi
  local missing=() p
  for p in "${packages[@]}"; do
    is_installed "$p" || missing+=("$p")
  done
  if ((${#missing[@]} == 0)); then
    say "dependencies: all ${#packages[@]} packages already installed"
    return 0
  fi
  local sudo=()
  if ((EUID != 0)); then
    command -v sudo >/dev/null 2>&1 ||
      die "missing packages: ${missing[*]}; run as root, or install them with apt-get"
    sudo=(sudo)
  fi
  say "installing missing packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# --- build -------------------------------------------------------------------
configure() {
  local werror=OFF
  [[ $mode == test ]] && werror=$WARNINGS_AS_ERRORS_IN_TEST
  say "configuring $build (Release, -O2, assertions on, -Wall -Wextra, warnings as errors: $werror)"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O2 \
    -DSUBDIV_WARNINGS_AS_ERRORS="$werror" >/dev/null ||
    die "cmake configuration failed (run: cmake -S . -B build to see why)"
}

# The sanitizer job (test mode): build-asan/ with AddressSanitizer and
# UndefinedBehaviorSanitizer, -O1 -g1 (line tables for the stacks), CGAL's
# assertions on; only SANITIZER_TARGETS are built and only the tests labelled
# SANITIZER_LABELS run. Any report stops the program (halt_on_error, no
# recovery) and fails its test.
sanitizer_job() {
  local flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all"
  say "configuring $build_asan (ASan + UBSan: $flags)"
  cmake -S "$root" -B "$build_asan" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DSUBDIV_WARNINGS_AS_ERRORS=OFF \
    -DSUBDIV_TEST_TIMEOUT_SCALE=10 \
    -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE >/dev/null ||
    die "cmake configuration of $build_asan failed (run: cmake -S . -B build-asan to see why)"
  say "building ${SANITIZER_TARGETS[*]} with sanitizers, $jobs jobs"
  cmake --build "$build_asan" -j "$jobs" --target "${SANITIZER_TARGETS[@]}" >"$build_asan/build.log" 2>&1 || {
    tail -n 60 "$build_asan/build.log" >&2
    die "the sanitizer build failed (the whole log: $build_asan/build.log)"
  }
  local labels
  labels="^($(IFS='|'; echo "${SANITIZER_LABELS[*]}"))\$"
  say "running the tests labelled ${SANITIZER_LABELS[*]} under the sanitizers (ctest -j $jobs)"
  (
    cd "$build_asan"
    export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:strict_string_checks=1}
    export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
    ctest --output-on-failure -j "$jobs" --timeout 1500 -L "$labels"
  ) || die "the tests under ASan + UBSan failed (above; build-asan/); the main tests were not run"
}

# The fuzz job (test mode, with the sanitizer job): src/scripts/fuzz.sh builds
# every target of src/fuzz/ with clang, ASan and UBSan, seeds it from
# ../shared/data/meshes and test/cli/, and runs it for FUZZ_SECONDS; a crash
# fails the run (the input is kept in build-fuzz/TARGET/crashes/).
fuzz_job() {
  say "fuzzing every target of src/fuzz/ for $FUZZ_SECONDS s each (src/scripts/fuzz.sh)"
  bash "$root/src/scripts/fuzz.sh" --seconds "$FUZZ_SECONDS" --build "$root/build-fuzz" ||
    die "the fuzz job failed (above; build-fuzz/); the main tests were not run"
}

install_missing
[[ $mode == deps ]] && exit 0
configure

if [[ $mode == demo ]]; then
  targets=$(cmake --build "$build" --target help 2>/dev/null || true)
  grep -Eq '(^|[[:space:]])cgal-subdiv(:|[[:space:]]|$)' <<<"$targets" ||
    die "this checkout has no cgal-subdiv target yet (see src/CMakeLists.txt)"
  say "building cgal-subdiv with $jobs jobs"
  cmake --build "$build" --target cgal-subdiv -j "$jobs" || die "building cgal-subdiv failed (see above)"
  exe=$build/src/cgal-subdiv
  [[ -x $exe ]] || die "$exe was not built"
  say "running: build/src/cgal-subdiv demo --output-dir out"
  "$exe" demo --output-dir "$root/out"
  exit 0
fi

# test
say "building everything with $jobs jobs"
cmake --build "$build" -j "$jobs" 2>&1 | tee "$build/build.log" || die "the build failed (see above)"
if ((sanitizers)); then
  sanitizer_job
  fuzz_job
else
  say "sanitizer and fuzz jobs skipped (--no-sanitizers)"
fi
say "running the tests (ctest -j $jobs)"
# ctest's summary stays the last thing printed, and its exit code is ours
cd "$build"
exec ctest --output-on-failure -j "$jobs" --timeout 1500
