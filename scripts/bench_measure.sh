#!/usr/bin/env bash
# Benchmark of the measurement layer (printed figures, not a timed test): ground-truth time and
# the total time of `shadowtune measure` per preset at 1280x720, on this machine.
# usage: scripts/bench_measure.sh [BUILD_DIR] [PRESET...]
#   BUILD_DIR defaults to build/release; presets default to the yard (presets/default.json) and
#   Truck Town (presets/scenes/truck-town.json, skipped when ../shared/assets is absent).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
shift || true
presets=("$@")
if [[ ${#presets[@]} == 0 ]]; then
  presets=("$root/presets/default.json")
  if [[ -d $root/../shared/assets/truck_town ]]; then
    presets+=("$root/presets/scenes/truck-town.json")
  else
    echo "note: ../shared/assets not found, Truck Town skipped" >&2
  fi
fi
out=$(mktemp -d) && trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
# One line per preset: "ground truth X s" is the rays for every pixel (BVH build reported apart
# in the progress line), "total" everything from loading the scene to the last figure.
"$build/shadowtune" measure "${presets[@]}" --out "$out" --size 1280x720
