#!/usr/bin/env bash
# The web-engine rows of docs/tuning.md's tuned table, measured in the engines themselves
# (`shadowtune engine-check`, docs/cli.md#engine-check): for each scene and engine with a tuned preset
# presets/tuned/<scene>-at-<engine>-budget.json, two checks on the scene's preset view: the engine's defaults
# (`engine-check presets/scenes/<scene>.json --engine E --defaults`) and the tuned preset exported to
# the engine's knobs (`engine-check presets/tuned/<scene>-at-<engine>-budget.json --engine E`). Prints one
# Markdown table: misclassified share in the engine with its defaults and with the exported tuned
# preset, the gain (defaults / tuned), the pixel agreement of engine and model in each check, and the
# knobs the engine lacks of the tuned preset (figures.json `lacks`). A scene and engine without a
# tuned preset is left out (listed on stderr).
# Each check's folder is OUT/<engine>/<scene>/{defaults,tuned}/, its output in OUT/logs/.
# Resumable: a check whose figures.json exists is not run again (FORCE=1 runs every check).
# Exits 1 at the end when a check failed.
#   scripts/tuned_in_engine.sh [ENGINES] [OUT]   (default "threejs babylon", out/tuned-in-engine)
# Needs build/release/shadowtune (builds nothing; BIN=PATH runs another, e.g. a copy a rebuild cannot
# swap mid-table), jq, node + Chromium + engines/node_modules (scripts/setup.sh) and ../shared/assets.
# SIZE=WxH changes the size (default 640x360).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
engines=${1:-threejs babylon}
out=${2:-$root/out/tuned-in-engine}
size=${SIZE:-640x360}
bin=${BIN:-$root/build/release/shadowtune}
[[ -x $bin ]] || { echo "error: $bin not built (cmake --build build/release)" >&2; exit 1; }
command -v jq >/dev/null || { echo "error: jq not found" >&2; exit 1; }
mkdir -p "$out/logs"
out=$(cd "$out" && pwd)

scenes=(truck-town dutch-ship fox living-room palm-tree-island zdm2-sauerbraten)

pct() { jq -r "$1 | if . == null then \"-\" else . * 100 | (. * 1000 | round) / 1000 | tostring + \" %\" end" "$2"; }

problems=()
# check ENGINE SCENE KIND PRESET [ARGS...]: runs one engine-check unless its figures.json exists;
# returns 1 (and records the problem) when it failed.
check() {
  local engine=$1 scene=$2 kind=$3 preset=$4
  shift 4
  local dir=$out/$engine/$scene/$kind log=$out/logs/$engine-$scene-$kind
  if [[ ${FORCE:-0} == 1 || ! -f $dir/figures.json ]]; then
    rm -f "$dir/figures.json"
    echo "running $engine $scene $kind ..." >&2
    local rc=0
    "$bin" engine-check "$preset" --engine "$engine" "$@" --size "$size" --out "$dir" \
      >"$log.stdout" 2>"$log.stderr" || rc=$?
    if [[ $rc != 0 || ! -f $dir/figures.json ]]; then
      local first
      first=$(grep -m1 -v '^[[:space:]]*$' "$log.stderr" || true)
      [[ -n $first ]] || first="exit $rc, nothing on stderr"
      # a failed check's figures.json must not count as done on the next run
      [[ -f $dir/figures.json ]] && mv "$dir/figures.json" "$dir/figures.failed.json"
      problems+=("$engine $scene $kind: failed: $first")
      return 1
    fi
  fi
  if ! jq -e '.agreement != null' "$dir/figures.json" >/dev/null; then
    problems+=("$engine $scene $kind: figures.json has no agreement")
    return 1
  fi
}

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
rows=()
for scene in "${scenes[@]}"; do
  for engine in $engines; do
    case $engine in threejs|babylon) ;; *) echo "error: unknown engine '$engine' (threejs, babylon)" >&2; exit 2 ;; esac
    tuned=$root/presets/tuned/$scene-at-$engine-budget.json
    if [[ ! -f $tuned ]]; then
      echo "no presets/tuned/$scene-at-$engine-budget.json: $scene left out for $engine" >&2
      continue
    fi
    ok=1
    check "$engine" "$scene" defaults "$root/presets/scenes/$scene.json" --defaults || ok=0
    check "$engine" "$scene" tuned "$tuned" || ok=0
    if ((!ok)); then
      rows+=("| $scene | $engine | failed (see stderr) | | | | | |")
      continue
    fi
    d=$out/$engine/$scene/defaults/figures.json
    t=$out/$engine/$scene/tuned/figures.json
    # gain: defaults' misclassified share / the tuned preset's, 2 significant digits (below 1: worse)
    gain=$(jq -rn --slurpfile d "$d" --slurpfile t "$t" '
      def sig2: (log10 | floor) as $e
        | if $e >= 1 then (. * 10 | round) / 10 else pow(10; 1 - $e) as $m | (. * $m | round) / $m end;
      ($d[0].engine.figures["accuracy.misclassified"]) as $a | ($t[0].engine.figures["accuracy.misclassified"]) as $b
      | if $a > 0 and $b > 0 then $a / $b | sig2 | tostring + "x" else "-" end')
    lacks=$(jq -r '.lacks // [] | if length == 0 then "—" else join("; ") end' "$t")
    rows+=("| $scene | $engine | $(pct '.engine.figures["accuracy.misclassified"]' "$d") | $(pct '.engine.figures["accuracy.misclassified"]' "$t") | $gain | $(pct .agreement "$d") | $(pct .agreement "$t") | ${lacks//|/\\|} |")
  done
done

echo "| scene | engine | misclassified in the engine, its defaults | with the exported tuned preset | gain | agreement, defaults | agreement, tuned | knobs the engine lacks (figures.json lacks) |"
echo "|---|---|---|---|---|---|---|---|"
if ((${#rows[@]})); then printf '%s\n' "${rows[@]}"; fi
echo
echo "size $size; machine: $(nproc) cores; load before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
if ((${#problems[@]})); then
  echo >&2
  echo "${#problems[@]} check(s) failed:" >&2
  printf '  %s\n' "${problems[@]}" >&2
  exit 1
fi
