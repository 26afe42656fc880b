#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): the soft ground truth of the sun's disc for
# Truck Town at 1280x720, at 16 and 64 rays per pixel, beside the point truth (one ray) of the
# same frames, in the same run. The budget of issue 12: 64 rays in at most 1.5 s on the 2-core
# machine. Needs ../shared/assets.
#   scripts/bench_soft_truth.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
runs=${2:-3}
st=$build/shadowtune
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scene=$(realpath ../shared/assets/truck_town/truck_town.gltf)
for rays in 16 64; do
  sed -e "s|\"scene\": \"[^\"]*\"|\"scene\": \"$scene\"|" -e '/"\$schema"/d' \
      -e "s|\"output\":|\"measure\": { \"sunRays\": $rays },\n  \"output\":|" presets/scenes/truck-town.json >"$out/rays$rays.json"
done
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
for rays in 16 64; do
  : >"$out/soft$rays" && : >"$out/hard$rays"
  for ((r = 0; r < runs; ++r)); do
    "$st" measure "$out/rays$rays.json" --size 1280x720 --no-flicker --frames 1 --out "$out/m" >"$out/log"
    line=$(grep -F '| ground truth' "$out/log")
    sed -E 's/.*\| ground truth ([0-9.]+) s, soft truth ([0-9.]+) s.*/\1/' <<<"$line" >>"$out/hard$rays"
    sed -E 's/.*\| ground truth ([0-9.]+) s, soft truth ([0-9.]+) s.*/\2/' <<<"$line" >>"$out/soft$rays"
  done
  hard=$(median <"$out/hard$rays") soft=$(median <"$out/soft$rays")
  echo "truck-town 1280x720, $rays rays over 0.53 deg: soft truth median $soft s over $runs runs;" \
       "point truth $hard s; ratio $(echo "scale=1; $soft / $hard" | bc)x"
done
grep -F 'against the sun' "$out/log" | sed -E 's/.*(against the sun[^|]*).*/last run: \1/'
