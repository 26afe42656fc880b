#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): every shadow filter on the yard and Truck Town at
# 1280x720 with 4 cascades of 2048^2, measured in one `shadowtune measure` run, as ratios to the
# hard 2x2 PCF of the same run. Columns: the shadow pass, the filter's own passes (moment maps and
# their blur), the main pass (filtering included) in GPU ms (medians), all shadow memory (depth
# array + the filter's maps), the nearest-test misclassification, the filtered error against the
# point-sun truth and against the soft truth of the sun's disc (light.angularDiameter 0.53, the
# real sun, RAYS rays per pixel: metrics/soft_accuracy.h), the last as a ratio to pcf2x2 too.
# Every depth-compare filter (hard, PCF, PCSS and the screen-space path's mask) gets receiver-plane
# bias, as seed 004 prescribes for wide kernels: without it their taps read acne on sloped ground
# and the error column would score the bias, not the filter. Moment filters have no compare to bias.
#   scripts/bench_filters.sh [BUILD_DIR] [FRAMES] [RAYS]   needs jq; Truck Town needs ../shared/assets
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
frames=${2:-5}
rays=${3:-16}
out=$(mktemp -d) && trap 'rm -rf "$out"' EXIT
scenes=("$root/presets/default.json")
if [[ -d $root/../shared/assets/truck_town ]]; then
  scenes+=("$root/presets/scenes/truck-town.json")
else
  echo "note: ../shared/assets not found, Truck Town skipped" >&2
fi
# name | filter object merged into the scene preset's filter
filters=(
  'pcf2x2|{"kind":"pcf2x2"}'
  'hard|{"kind":"hard"}'
  'pcf5-box|{"kind":"pcf-nxn","size":5}'
  'pcf5-gauss-pad|{"kind":"pcf-nxn","size":5,"weights":"gaussian","padding":true}'
  'pcss7|{"kind":"pcss","size":7,"blockerTaps":5,"pcssMaxRadius":8}'
  'vsm-r3|{"kind":"vsm","blurRadius":3}'
  'vsm-r3-mips|{"kind":"vsm","blurRadius":3,"mipmaps":true}'
  'evsm2-r3|{"kind":"evsm2","blurRadius":3}'
  'evsm4-r3|{"kind":"evsm4","blurRadius":3}'
  'evsm4-r3-16|{"kind":"evsm4","blurRadius":3,"moments16":true}'
  'msm-r3|{"kind":"msm","blurRadius":3}'
  'msm-r3-16|{"kind":"msm","blurRadius":3,"moments16":true}'
  'screen-hard-r4|{"kind":"hard","screenSpace":"blur","screenDownsample":2,"screenBlurRadius":4}'
)
presets=()
mkdir "$out/presets"
for scene in "${scenes[@]}"; do
  stem=$(basename "$scene" .json)
  for f in "${filters[@]}"; do
    name=${f%%|*}
    # In the temporary folder, not beside the scene preset (a preset there would join the
    # presets/*.json globs of a concurrent cmake run), so a relative scene path is made absolute.
    p="$out/presets/$stem-$name.json"
    jq --argjson f "${f#*|}" --argjson rays "$rays" --arg dir "$(dirname "$scene")" '.filter = (.filter + $f)
      | .cascades.count = 4 | .cascades.mapSize = 2048
      | .bias.receiverPlane = ((.filter.kind | IN("vsm", "evsm2", "evsm4", "msm")) | not)
      | .path = {"frames": 0, "keyframes": []} | .light.angularDiameter = 0.53 | .measure.sunRays = $rays
      | .scene |= (if startswith("builtin:") or startswith("/") then . else $dir + "/" + . end)
      | del(."$schema")' "$scene" >"$p"
    presets+=("$p")
  done
done
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); Mesa llvmpipe"
"$build/shadowtune" measure "${presets[@]}" --out "$out" --size 1280x720 --frames "$frames" --no-flicker >"$out/log" 2>&1 ||
  { cat "$out/log" >&2; exit 1; }
for scene in "${scenes[@]}"; do
  stem=$(basename "$scene" .json)
  base="$out/$stem-pcf2x2/metrics.json"
  echo
  echo "$stem, 1280x720, 4x2048; ratios to pcf2x2 (absolute in brackets); soft truth 0.53 deg, $rays rays"
  printf '%-16s %16s %16s %16s %18s %11s %10s %18s\n' filter "shadow ms" "filter ms" "main ms" "memory MiB" \
    "misclass %" "point err" "soft err"
  for f in "${filters[@]}"; do
    name=${f%%|*}
    jq -r --arg name "$name" --slurpfile b "$base" '
      def ratio(a; b): if b > 0 then (a / b * 100 | round / 100 | tostring) + "x" else "-" end;
      .cost as $c | $b[0].cost as $k |
      [$name,
       ratio($c.gpuShadowMs; $k.gpuShadowMs) + " (" + ($c.gpuShadowMs * 10 | round / 10 | tostring) + ")",
       ($c.gpuFilterMs * 10 | round / 10 | tostring),
       ratio($c.gpuMainMs; $k.gpuMainMs) + " (" + ($c.gpuMainMs * 10 | round / 10 | tostring) + ")",
       ratio($c.shadowMapBytes + $c.filterMapBytes; $k.shadowMapBytes + $k.filterMapBytes) + " ("
         + (($c.shadowMapBytes + $c.filterMapBytes) / 1048576 | round | tostring) + ")",
       (.accuracy.misclassified * 1000 | round / 10 | tostring),
       (.accuracy.filteredError * 10000 | round / 10000 | tostring),
       ratio(.soft.filteredError; $b[0].soft.filteredError) + " ("
         + (.soft.filteredError * 10000 | round / 10000 | tostring) + ")"]
      | "\(.[0])|\(.[1])|\(.[2])|\(.[3])|\(.[4])|\(.[5])|\(.[6])|\(.[7])"' "$out/$stem-$name/metrics.json" |
      awk -F'|' '{printf "%-16s %16s %16s %16s %18s %11s %10s %18s\n", $1, $2, $3, $4, $5, $6, $7, $8}'
  done
done
