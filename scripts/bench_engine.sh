#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): how long one `shadowtune engine-check` takes, the
# issue's goal being at most 10 s per check. Truck Town with the engine's defaults at 640x360, RUNS
# times after one warm-up run (WARMUP=0 skips it); each run is a whole process, Chromium's start
# and shutdown included. Prints the median, min and max wall seconds, the medians of the engine's
# own timings from figures.json (startMs: Chromium's launch, loadMs: page + glTF, renderMs: set-up,
# shader compilation, render and readback, totalMs: the driver's whole run), and the machine's load
# before and after (a loaded machine stretches every figure: quote medians).
#   scripts/bench_engine.sh [ENGINE] [RUNS]   (default threejs, 5)
# Needs build/release/shadowtune (builds nothing), jq, node + Chromium + engines/node_modules
# (scripts/setup.sh) and ../shared/assets/truck_town.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
engine=${1:-threejs}
runs=${2:-5}
bin=$root/build/release/shadowtune
preset=$root/presets/scenes/truck-town.json
[[ -x $bin ]] || { echo "error: $bin not built (cmake --build build/release)" >&2; exit 1; }
command -v jq >/dev/null || { echo "error: jq not found" >&2; exit 1; }
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "error: RUNS must be a positive whole number, got '$runs'" >&2; exit 2; }
out=$(mktemp -d) && trap 'rm -rf "$out"' EXIT

# median, min and max of the numbers on stdin, one a line
stats() { sort -g | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "median %.2f, min %.2f, max %.2f", m, v[1], v[NR] }'; }
median() { stats | sed 's/,.*//; s/median //'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "engine-check $(basename "$preset") --engine $engine --defaults --size 640x360: ${WARMUP:-1} warm-up + $runs runs"
echo "load before: $(uptime | sed 's/.*load average: //')"
for ((i = 1 - ${WARMUP:-1}; i <= runs; i++)); do
  dir=$out/run$i
  t0=$(date +%s.%N)
  if ! "$bin" engine-check "$preset" --engine "$engine" --defaults --size 640x360 --out "$dir" >"$dir.log" 2>&1; then
    echo "error: run $i failed:" >&2
    tail -5 "$dir.log" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  if ((i >= 1)); then echo "$t0 $t1" | awk '{ printf "%.3f\n", $2 - $1 }' >>"$out/wall"; fi
done
echo "load after:  $(uptime | sed 's/.*load average: //')"
echo
echo "wall seconds (the whole process):      $(stats <"$out/wall")"
echo "engine-check's own seconds:            $(jq -r '.seconds' "$out"/run[1-9]*/figures.json | stats)"
for t in startMs loadMs renderMs totalMs; do
  printf '%-38s %s\n' "engine $t (median):" "$(jq -r ".engineTimings.$t" "$out"/run[1-9]*/figures.json | median)"
done
m=$(median <"$out/wall")
echo "goal <= 10 s per engine-check: $(awk -v m="$m" 'BEGIN { print (m <= 10 ? "met" : "missed") }') (median $m s)"
