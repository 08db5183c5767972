#!/usr/bin/env bash
# Installs what is missing, builds highlift and runs the main job on the bundled A380-class
# flap transmission (both wings; the embedded component database is the default):
#   validate -> info -> estimate -> check -> size -> modes -> peak (single-DOF and transient)
#   -> simulate (the rupture with wing-tip brakes, full resolution) -> export (Modelica)
#   -> report (all of it in one HTML file: build/demo-report.html).
# Exit code 1 of an analysis means it found violated requirements or negative margins: the demo
# reports it and goes on. Anything else (invalid input, a crash) stops the demo with that code.
# Usage: scripts/demo.sh [PROJECT.json]      (from anywhere; default the A380-class example)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs" --target highlift

example=${1:-examples/a380_class_flaps.json}
hl=build/cli/highlift
findings=()

run() {
  echo
  echo "\$ highlift $*"
  set +e
  "$hl" "$@"
  local rc=$?
  set -e
  case $rc in
    0) ;;
    1) findings+=("highlift $1: requirements or margins violated (exit 1)") ;;
    *) echo "demo: 'highlift $*' failed with exit code $rc" >&2; exit "$rc" ;;
  esac
}

run validate "$example"
run info "$example" --brief
run estimate "$example"
run check "$example"
run size "$example"
run modes "$example"
run peak "$example" --no-intervals --transient
if grep -q '"rupture_wtb"' "$example"; then
  run simulate "$example" --scenario rupture_wtb --energy --output build/demo-rupture_wtb.csv \
    --signals pdu.w,appu_left.w,appu_right.w,wtb_left.tau,shaft_l7.tau,stl_left.tau,monitor.wtb
fi
run export "$example" --modelica build/demo-modelica --model reduced --scenario rupture_wtb
run report "$example" --out build/demo-report.html

echo
echo "== main job done on $example"
if [ ${#findings[@]} -eq 0 ]; then
  echo "no violated requirements or negative margins"
else
  printf '  %s\n' "${findings[@]}"
fi
