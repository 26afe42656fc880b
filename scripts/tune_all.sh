#!/usr/bin/env bash
# Tunes each scene against each reference at that reference's modelled budget and keeps the tuned
# preset as presets/tuned/<scene>-at-<reference>-budget.json (issue 19's proof on real scenes), with the
# tune's folder (journal, front, explain.md, summary.json) under OUT. Reruns resume: a finished
# tune's folder makes no new evaluations. Prints one line per tune; scripts/tuned_table.sh turns
# the folders into docs/tuning.md's tables.
#   scripts/tune_all.sh [BUILD_DIR] [EVALUATIONS] [SIZE] [OUT] -- [REFERENCE.json ...]
# Defaults: build/release, 40 evaluations, 320x180, out/tuned-runs, every seed preset and engine
# default. Needs ../shared/assets. ONLY="run run ..." (names as <scene>-at-<reference>-budget) tunes just
# those: with more EVALUATIONS, a finished tune's walk goes on from its journal (docs/tuning.md#running).
#   ONLY="$(scripts/tuned_table.sh OUT | awk -F' [|] ' '/missed/ {print $1}' | tr -d '| ')" scripts/tune_all.sh build/release 80 320x180 OUT
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
evaluations=${2:-40}
size=${3:-320x180}
out=${4:-$root/out/tuned-runs}
shift $(( $# < 4 ? $# : 4 )) || true
[ "${1:-}" = "--" ] && shift
cd "$root"
if [ $# -gt 0 ]; then refs=("$@"); else
  refs=(presets/ogldev-49.json presets/nvidia-sdk.json presets/dx-sdk-csm11.json presets/soft-shadows-blog.json
        presets/vsm11.json presets/xna-atlas.json presets/engines/*.json)
fi
scenes=(presets/default.json presets/scenes/*.json)
mkdir -p presets/tuned "$out"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json); [ "$name" = default ] && name=yard
  for ref in "${refs[@]}"; do
    run="$name-at-$(basename "$ref" .json)-budget"
    if [ -n "${ONLY:-}" ] && [[ " $(echo $ONLY) " != *" $run "* ]]; then continue; fi
    start=$(date +%s)
    if ! EGL_PLATFORM=surfaceless "$build/shadowtune" tune "$scene" --budget-from "$ref" --evaluations "$evaluations" \
         --size "$size" --out "$out/$run" > "$out/$run.log" 2>&1; then
      echo "$run: failed ($(tail -1 "$out/$run.log"))"; continue
    fi
    # The tuned preset next to the scene presets: the scene path is the scene preset's own, one
    # folder deep under presets/ as presets/scenes/ is.
    jq --arg scene "$(jq -r .scene "$scene")" '.scene = $scene' "$out/$run/tuned.json" > "presets/tuned/$run.json.tmp"
    mv "presets/tuned/$run.json.tmp" "presets/tuned/$run.json"
    echo "$run: $(tail -1 "$out/$run.log") ($(( $(date +%s) - start )) s, load $(cut -d' ' -f1 /proc/loadavg))"
  done
done
