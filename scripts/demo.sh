#!/usr/bin/env bash
# Installs what is missing, builds highlift and runs the main job on the bundled A380-class
# flap transmission (the embedded component database is the default).
# Usage: scripts/demo.sh            (from the project root)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs" --target highlift

example=examples/a380_class_flaps.json
hl=build/cli/highlift
set -x
"$hl" validate "$example"
"$hl" info "$example"
