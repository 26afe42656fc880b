#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): the shipped Truck Town sweep at 640x360 in one
# process, and the same kind of point measured by `shadowtune measure` in a process of its own,
# one process per point, in the same run. Needs ../shared/assets.
#   scripts/bench_sweep.sh [BUILD_DIR] [POINTS_FOR_THE_SEPARATE_RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
separate=${2:-8}
st=$build/shadowtune
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s.%N)
"$st" sweep presets/sweeps/truck-town.json --out "$out/sweep" >"$out/sweep.log" 2>&1
sweep_s=$(echo "$(date +%s.%N) - $start" | bc)
points=$(ls "$out/sweep/points" | wc -l)
# The separate runs measure front points (loadable presets, their scene paths rewritten).
mapfile -t presets < <(ls "$out"/sweep/front/*.json | head -n "$separate")
start=$(date +%s.%N)
for p in "${presets[@]}"; do "$st" measure "$p" --out "$out/measure" >/dev/null 2>&1; done
separate_s=$(echo "$(date +%s.%N) - $start" | bc)
n=${#presets[@]}
per_sweep=$(echo "scale=3; $sweep_s / $points" | bc)
per_separate=$(echo "scale=3; $separate_s / $n" | bc)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "truck-town sweep: $points points in $sweep_s s, $per_sweep s per point (one process)"
echo "measure, one process per point: $n points in $separate_s s, $per_separate s per point"
echo "one-process speed-up per point: $(echo "scale=2; $per_separate / $per_sweep" | bc)x"
