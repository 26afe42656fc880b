#!/usr/bin/env bash
# shadowtune's model of the web engines against the engines themselves (`shadowtune engine-check`,
# docs/cli.md#engine-check): for each engine, on the yard, the box over a plane and the six real
# scenes, the engine's defaults and three other settings of its own knobs, at 640x360. Prints one
# Markdown table per engine: agreement (share of scored pixels where engine and model say the same),
# misclassified share and soft filtered error of the engine and of shadowtune's model, and the
# seconds of the check (Chromium's start included). The knob files are written into OUT/knobs/;
# each check's folder (engine.png, model.png, disagreement.png, figures.json, ...) is
# OUT/<engine>/<scene>/<settings>/, its output in OUT/logs/.
# Resumable: a row whose figures.json exists is not run again (FORCE=1 runs every row).
# Exits 1 at the end when a check failed or an agreement is below 0.98 (listed on stderr).
#   scripts/engine_table.sh [ENGINES] [OUT]   (default "threejs babylon", out/engine-table)
# Needs build/release/shadowtune (builds nothing), jq, node + Chromium + engines/node_modules
# (scripts/setup.sh) and ../shared/assets for the six real scenes. SIZE=WxH changes the size; BIN=PATH
# runs another shadowtune (a copy, so a rebuild cannot swap it mid-table). "factor agreement": the same
# state or factors within 0.1 (acne under a filter hovers at 0.5, where a hair flips the state).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
engines=${1:-threejs babylon}
out=${2:-$root/out/engine-table}
size=${SIZE:-640x360}
bin=${BIN:-$root/build/release/shadowtune}
[[ -x $bin ]] || { echo "error: $bin not built (cmake --build build/release)" >&2; exit 1; }
command -v jq >/dev/null || { echo "error: jq not found" >&2; exit 1; }
mkdir -p "$out/knobs" "$out/logs"
out=$(cd "$out" && pwd)

scenes=(
  "yard=presets/default.json"
  "box-over-plane=presets/box-over-plane.json"
)
for s in truck-town dutch-ship fox living-room palm-tree-island zdm2-sauerbraten; do
  scenes+=("$s=presets/scenes/$s.json")
done

# The settings of each engine besides its defaults, in its own knob names (engines/<engine>/page.js
# refuses unknown keys; renderer/export/engine_knobs_<engine>.cpp checks names and ranges).
write_knobs() {
  local k=$out/knobs
  # three.js (CSM addon): bias toward the light + normal offset; one-point PCF on smaller maps;
  # uniform splits in 4 cascades with both faces casting.
  echo '{"shadowBias": -0.0005, "normalBias": 0.02}' >"$k/threejs-bias.json"
  echo '{"radius": 0, "shadowMapSize": 1024}' >"$k/threejs-radius0-1024.json"
  echo '{"mode": "uniform", "cascades": 4, "shadowSide": "double"}' >"$k/threejs-uniform4-double.json"
  # Babylon (CascadedShadowGenerator): more bias; 2x2 PCF on 2048 maps; 2 cascades without blending.
  echo '{"bias": 0.001}' >"$k/babylon-bias.json"
  echo '{"filteringQuality": "low", "mapSize": 2048}' >"$k/babylon-low-2048.json"
  echo '{"numCascades": 2, "cascadeBlendPercentage": 0}' >"$k/babylon-2cascades-noblend.json"
}
write_knobs

settings_of() {
  echo defaults
  case $1 in
    threejs) echo bias radius0-1024 uniform4-double ;;
    babylon) echo bias low-2048 2cascades-noblend ;;
  esac
}

pct() { jq -r "$1 | if . == null then \"-\" else . * 100 | (. * 1000 | round) / 1000 | tostring + \" %\" end" "$2"; }

problems=()
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for engine in $engines; do
  case $engine in threejs|babylon) ;; *) echo "error: unknown engine '$engine' (threejs, babylon)" >&2; exit 2 ;; esac
  rows=()
  for entry in "${scenes[@]}"; do
    scene=${entry%%=*}
    preset=$root/${entry#*=}
    for setting in $(settings_of "$engine"); do
      dir=$out/$engine/$scene/$setting
      log=$out/logs/$engine-$scene-$setting
      knobs=(--defaults)
      [[ $setting == defaults ]] || knobs=(--knobs "$out/knobs/$engine-$setting.json")
      if [[ ${FORCE:-0} == 1 || ! -f $dir/figures.json ]]; then
        rm -f "$dir/figures.json"
        echo "running $engine $scene $setting ..." >&2
        rc=0
        "$bin" engine-check "$preset" --engine "$engine" "${knobs[@]}" --size "$size" --out "$dir" \
          >"$log.stdout" 2>"$log.stderr" || rc=$?
        if [[ $rc != 0 || ! -f $dir/figures.json ]]; then
          first=$(grep -m1 -v '^[[:space:]]*$' "$log.stderr" || true)
          [[ -n $first ]] || first="exit $rc, nothing on stderr"
          [[ $rc == 0 ]] && first="no figures.json ($first)"
          # a failed check's figures.json must not count as done on the next run
          [[ -f $dir/figures.json ]] && mv "$dir/figures.json" "$dir/figures.failed.json"
          rows+=("| $scene | $setting | failed: ${first//|/\\|} | | | | | | |")
          problems+=("$engine $scene $setting: failed: $first")
          continue
        fi
      fi
      f=$dir/figures.json
      agreement=$(jq -r '.agreement // empty' "$f")
      if [[ -z $agreement ]]; then
        rows+=("| $scene | $setting | failed: figures.json has no agreement | | | | | | |")
        problems+=("$engine $scene $setting: figures.json has no agreement")
        continue
      fi
      rows+=("| $scene | $setting | $(pct .agreement "$f") | $(pct .factorAgreement "$f") | $(pct '.engine.figures["accuracy.misclassified"]' "$f") | $(pct '.model.figures["accuracy.misclassified"]' "$f") | $(jq -r '.engine.figures["soft.filteredError"] | (. * 10000 | round) / 10000' "$f") | $(jq -r '.model.figures["soft.filteredError"] | (. * 10000 | round) / 10000' "$f") | $(jq -r '.seconds | (. * 10 | round) / 10 | tostring | if test("[.]") then . else . + ".0" end' "$f") |")
      if jq -e '.agreement < 0.98' "$f" >/dev/null; then
        problems+=("$engine $scene $setting: agreement $(pct .agreement "$f") < 98 %")
      fi
    done
  done
  version=$(jq -r '.engine.version // empty' "$out/$engine"/*/defaults/figures.json 2>/dev/null | head -1 || true)
  echo
  echo "### $engine${version:+ $version}, $size"
  echo
  echo "| scene | settings | agreement | factor agreement | misclassified engine | misclassified shadowtune | filtered error engine | filtered error shadowtune | seconds |"
  echo "|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
done
echo
for engine in $engines; do
  for setting in $(settings_of "$engine"); do
    [[ $setting == defaults ]] || echo "$engine $setting: $(cat "$out/knobs/$engine-$setting.json")"
  done
done
echo "machine: $(nproc) cores; load before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg) (rows skipped as done keep the seconds of their own run)"
if ((${#problems[@]})); then
  echo >&2
  echo "${#problems[@]} row(s) failed or agree on less than 98 %:" >&2
  printf '  %s\n' "${problems[@]}" >&2
  exit 1
fi
