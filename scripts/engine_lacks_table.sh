#!/usr/bin/env bash
# "What your engine lacks, in numbers": for each engine-bound tune of scripts/engine_tune_table.sh
# (IN/<engine>/<scene>/tuned.json, `shadowtune tune --engine`), what one knob the engine does not
# offer would buy on top of the tuned knobs. Each variant is the tuned preset with one change
# (jq on the preset JSON, docs/presets.md):
#   fit-samples     a light box fitted to the visible samples   .cascades.fit = "samples"
#                   (godot: and .cascades.zExtension = "pancake", casters in front clamped, see below)
#   slope-bias      a slope-scaled bias                          .bias.slope = 1 (texels; constant kept)
#   normal-texels   a normal offset in texels (threejs, babylon: their normalBias is metres)
#                                                                .bias.normalOffsetUnit = "texels", .bias.normalOffset = 0.5
#   receiver-plane  a receiver-plane bias                        .bias.receiverPlane = true
#   back-faces      back faces casting (babylon only: it draws front faces; three.js has shadowSide,
#                   Godot back faces through reverse cull)       .cascades.casterFaces = "back"
#   blend           blending between cascades (unity only)       .cascades.blendBand = 0.1
# (normal-texels also for unreal, whose CSM has no normal offset at all.)
# The tuned preset and its variants are measured together with `shadowtune measure --no-flicker
# --frames 1` on the preset's own camera view only (the first of the tune's tuned views), at the
# preset's output size; the figures are shadowtune's (for three.js and Babylon.js its model of the
# engine, which engine-check holds against the engines), read from measure's metrics.json:
# accuracy.misclassified, soft.filteredError, cost.modelMs (modelled, not timed).
# Prints one Markdown table: engine, scene, feature, misclassified tuned -> with the feature, soft
# filtered error tuned -> with, modelled cost change; then the load before and after.
# The variants are written beside tuned.json (IN/<engine>/<scene>/lacks-<feature>.json, so that its
# relative scene path resolves), the measurements into IN/<engine>/<scene>/lacks/<name>/metrics.json,
# measure's output into IN/logs/lacks-<engine>-<scene>.{stdout,stderr}.
# Resumable: a folder whose every metrics.json exists is not measured again (FORCE=1 measures all).
# A folder without tuned.json, or whose measure fails, gives a row saying why and the table goes on;
# exit 1 at the end when any did (listed on stderr).
#   scripts/engine_lacks_table.sh [IN]   (default out/engine-tune-table)
# ENGINES="threejs babylon godot unity unreal bevy filament" and SCENES="yard truck-town ..." pick rows; BIN=PATH runs another
# shadowtune (default build/release/shadowtune; builds nothing). Needs jq and ../shared/assets.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
engines=${ENGINES:-threejs babylon godot unity unreal bevy filament}
scenes=${SCENES:-yard truck-town dutch-ship fox living-room palm-tree-island zdm2-sauerbraten}
in=${1:-${IN:-$root/out/engine-tune-table}}
bin=${BIN:-$root/build/release/shadowtune}
[[ -x $bin ]] || { echo "error: $bin not built (cmake --build build/release)" >&2; exit 1; }
command -v jq >/dev/null || { echo "error: jq not found" >&2; exit 1; }
[[ -d $in ]] || { echo "error: $in: no such folder (run scripts/engine_tune_table.sh first)" >&2; exit 1; }
in=$(cd "$in" && pwd)
mkdir -p "$in/logs"

# The features each engine lacks, as "name|label|jq filter".
features_of() {
  case $1 in
    # Godot's tuned boxes are spheres whose depth holds the casters, with a short (or no) reach
    # beyond: fitted to the samples, such a box cuts the casters toward the sun (truck-town with
    # pancake 0: 0.93 -> 11.2 % misclassified, false light). The samples fit keeps them by clamping
    # them onto the box's near plane, as Godot's own pancake does.
    godot) echo 'fit-samples|light box fitted to the visible samples (casters clamped as by a pancake)|.cascades.fit = "samples" | .cascades.zExtension = "pancake"' ;;
    *) echo 'fit-samples|light box fitted to the visible samples|.cascades.fit = "samples"' ;;
  esac
  case $1 in
    # Unreal (ShadowSlopeBias) and Filament (polygonOffsetSlope) have a slope bias; Unity's is fixed at 2.5
    unreal|filament) ;;
    unity) echo 'slope-bias|a slope bias other than the fixed 2.5 (1 texel)|.bias.slope = 1.0' ;;
    *) echo 'slope-bias|slope-scaled bias (1 texel)|.bias.slope = 1.0' ;;
  esac
  case $1 in
    threejs|babylon) echo 'normal-texels|normal offset in texels (0.5)|.bias.normalOffsetUnit = "texels" | .bias.normalOffset = 0.5' ;;
    unreal) echo 'normal-texels|normal offset (0.5 texels)|.bias.normalOffsetUnit = "texels" | .bias.normalOffset = 0.5' ;;
    unity) echo 'blend|blending between cascades (0.1 of a cascade)|.cascades.blendBand = 0.1' ;;
  esac
  echo 'receiver-plane|receiver-plane bias|.bias.receiverPlane = true'
  case $1 in
    babylon) echo 'back-faces|back faces casting|.cascades.casterFaces = "back"' ;;
  esac
}

pct() { jq -r '.accuracy.misclassified | if . == null then "-" else . * 100 | (. * 1000 | round) / 1000 | tostring + " %" end' "$1"; }
# the soft filtered error to 3 significant digits (the tuned presets' are 1e-4 to 1e-2)
soft() { jq -r '.soft.filteredError | if . == null then "-" elif . == 0 then "0" else pow(10; 2 - (log10 | floor)) as $m | (. * $m | round) / $m | tostring end' "$1"; }

rows=()
problems=()
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
echo "load before: $load_before" >&2
for engine in $engines; do
  for scene in $scenes; do
    dir=$in/$engine/$scene
    if [[ ! -f $dir/tuned.json ]]; then
      rows+=("| $engine | $scene | (no tuned.json: the tune failed or has not run) | | | |")
      problems+=("$engine $scene: no $dir/tuned.json")
      continue
    fi
    names=(tuned)
    labels=("tuned")
    presets=("$dir/tuned.json")
    while IFS='|' read -r name label filter; do
      jq "$filter" "$dir/tuned.json" >"$dir/lacks-$name.json.tmp"
      mv "$dir/lacks-$name.json.tmp" "$dir/lacks-$name.json"
      names+=("lacks-$name")
      labels+=("$label")
      presets+=("$dir/lacks-$name.json")
    done < <(features_of "$engine")
    done_all=1
    for n in "${names[@]}"; do [[ -f $dir/lacks/$n/metrics.json ]] || done_all=0; done
    log=$in/logs/lacks-$engine-$scene
    if [[ ${FORCE:-0} == 1 || $done_all == 0 ]]; then
      rm -rf "$dir/lacks"
      echo "measuring $engine $scene: tuned + $((${#names[@]} - 1)) variants ... (load $(cut -d' ' -f1 /proc/loadavg))" >&2
      rc=0
      "$bin" measure "${presets[@]}" --out "$dir/lacks" --no-flicker --frames 1 >"$log.stdout" 2>"$log.stderr" || rc=$?
      if [[ $rc != 0 ]]; then
        why=$(grep -m1 -iE 'error' "$log.stderr" || true)
        [[ -n $why ]] || why=$(grep -v '^[[:space:]]*$' "$log.stderr" | tail -1 || true)
        problems+=("$engine $scene: measure exit $rc: ${why:-nothing on stderr} (log $log.stderr)")
      fi
    fi
    base=$dir/lacks/tuned/metrics.json
    if [[ ! -f $base ]]; then
      why=$(grep -m1 -iE 'error' "$log.stderr" 2>/dev/null || true)
      rows+=("| $engine | $scene | (measure failed: ${why//|/\\|}) | | | |")
      continue
    fi
    for i in "${!names[@]}"; do
      ((i > 0)) || continue
      m=$dir/lacks/${names[$i]}/metrics.json
      if [[ ! -f $m ]]; then
        why=$(grep -m1 -F "${names[$i]}" "$log.stderr" 2>/dev/null || true)
        rows+=("| $engine | $scene | ${labels[$i]} | not measured${why:+: ${why//|/\\|}} | | |")
        problems+=("$engine $scene ${names[$i]}: not measured${why:+: $why}")
        continue
      fi
      cost=$(jq -rn --slurpfile a "$base" --slurpfile b "$m" '
        $a[0].cost.modelMs as $x | $b[0].cost.modelMs as $y
        | if $x == null or $y == null then "-"
          else ((($y - $x) * 10 | round) / 10) as $d
            | (if $d >= 0 then "+" else "" end) + ($d | tostring | if test("[.]") then . else . + ".0" end) + " ms ("
              + (if $y >= $x then "+" else "" end) + ((($y / $x - 1) * 100) | round | tostring) + " %)" end')
      rows+=("| $engine | $scene | ${labels[$i]} | $(pct "$base") -> $(pct "$m") | $(soft "$base") -> $(soft "$m") | $cost |")
    done
  done
done
echo
echo "| engine | scene | feature | misclassified: tuned -> with it | soft filtered: tuned -> with it | modelled cost change |"
echo "|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"
echo
echo "measured on each preset's own camera view (the tune's first view) at its output size, --no-flicker;"
echo "machine: $(nproc) cores; load before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
if ((${#problems[@]})); then
  echo >&2
  echo "${#problems[@]} problem(s):" >&2
  printf '  %s\n' "${problems[@]}" >&2
  exit 1
fi
