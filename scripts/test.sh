#!/usr/bin/env bash
# Installs what is missing, builds highlift and passes all tests: first a release build, then
# the libFuzzer targets for a bounded time (scripts/fuzz.sh), then the same tests under
# AddressSanitizer + UndefinedBehaviorSanitizer.
# Usage: scripts/test.sh            (from the project root; CI runs exactly this)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

# The wall time of each phase, printed as it ends and listed again at the end (docs/performance.md
# quotes them from the CI's log).
phase_start=$SECONDS
phases=""
phase_done() {
  local took=$((SECONDS - phase_start))
  echo "== $1: ${took} s"
  phases="$phases  $1: ${took} s"$'\n'
  phase_start=$SECONDS
}
trap 'echo "== phase times (wall) so far:"; printf "%s" "$phases"' EXIT

scripts/install-deps.sh
phase_done "installation"

echo "== release build and tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"
phase_done "release build"
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 900
phase_done "release tests"

echo "== libFuzzer targets (clang, ASan + UBSan), bounded time each"
scripts/fuzz.sh "${HIGHLIFT_FUZZ_SECONDS:-25}"
phase_done "fuzz targets (build and runs)"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g0" \
      -DHIGHLIFT_SANITIZE=ON -DHIGHLIFT_BUILD_BENCHMARKS=OFF
cmake --build build-asan -j "$jobs"
phase_done "sanitizer build"
# LeakSanitizer: the known leak inside Debian's UDUNITS-2 on a failed parse is suppressed
# (fuzz/lsan.supp); any leak of ours still fails.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$PWD/fuzz/lsan.supp" \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" --timeout 1800 -LE no_sanitize
phase_done "sanitizer tests"
