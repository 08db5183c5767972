#!/usr/bin/env bash
# Builds the libFuzzer targets in fuzz/ with clang (ASan + UBSan; core, the constraint parser,
# componentdb, the report's page renderer, the campaign library; never export) and runs each for a bounded time on its seed
# corpus: fuzz/corpus/<target>/ (checked-in seeds and regression inputs) plus, for the project
# loader, the example projects. New corpus entries go to a scratch folder, not into the tree.
# A crash stops the script (exit 1) and leaves the reproducer in build-fuzz/findings/; add it
# to fuzz/corpus/<target>/ and a unit test beside the behaviour it breaks.
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 25; HIGHLIFT_FUZZ_SECONDS also works).
# Budget on 2 cores: a few minutes to build (the campaign store target links the campaign
# library and with it the simulator), 7 x 25 s to run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-${HIGHLIFT_FUZZ_SECONDS:-25}}
jobs=$(nproc 2>/dev/null || echo 2)
build=build-fuzz

start=$(date +%s)
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
      -DHIGHLIFT_FUZZ=ON -DHIGHLIFT_BUILD_TESTS=OFF -DHIGHLIFT_BUILD_BENCHMARKS=OFF > "$build.configure.log" \
  || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$jobs" --target fuzz_all
echo "fuzz: build $(( $(date +%s) - start )) s"

mkdir -p "$build/findings"
status=0
for target in project constraint units db_import db_where campaign_store report_html; do
  scratch=$(mktemp -d)
  seeds=(fuzz/corpus/$target)
  if [ "$target" = project ]; then
    mkdir -p "$scratch/examples" && cp examples/*.json "$scratch/examples/"
    seeds+=("$scratch/examples")
  fi
  mkdir -p "$scratch/new"
  log="$build/findings/fuzz_$target.log"
  if ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
     LSAN_OPTIONS=suppressions=fuzz/lsan.supp \
     "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=200000 \
       -print_final_stats=1 -artifact_prefix="$build/findings/${target}_" "$scratch/new" "${seeds[@]}" > "$log" 2>&1; then
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz: $target: $execs inputs in ${seconds} s, no findings"
  else
    echo "fuzz: $target: FINDING (see $log and $build/findings/${target}_*)"
    tail -40 "$log"
    status=1
  fi
  rm -rf "$scratch"
done
echo "fuzz: total $(( $(date +%s) - start )) s"
exit $status
