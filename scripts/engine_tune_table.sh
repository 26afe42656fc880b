#!/usr/bin/env bash
# Engine-bound tunes (`shadowtune tune PRESET --engine E`, docs/cli.md#tune, docs/engines.md) on the
# yard and the six real scenes, with the tune's default options (80 evaluations, 4 views with one
# held out, the engine defaults' modelled cost as the budget). Prints one Markdown table per engine:
#   - the engine defaults' and the tuned knobs' modelled misclassified share, soft filtered error and
#     modelled cost on the tuned views (summary.json's references."<engine>-defaults".tuned and
#     tuned.tuned), and the modelled misclassified share on the held-out view, defaults -> tuned;
#   - for threejs and babylon, the engine itself (summary.json's engine object, engine-check run by
#     the tune on every view): misclassified with its defaults -> with the tuned knobs on the tuned
#     views, and the tuned knobs' pixel agreement between engine and model; the other engines do not
#     run here, their figures are shadowtune's model of them ("model only");
#   - the tune's seconds: wall clock of the command (engine-check included) and the search's own
#     (summary.json's secondsAllRuns);
#   - "goal": met when the tuned modelled cost is at most the defaults', and the tuned modelled
#     misclassified share and soft filtered error are at most half the defaults', and (threejs,
#     babylon) the engine's own misclassified share with the tuned knobs is at most half its defaults';
#     else "missed (...)" naming the parts missed, with the tuned/defaults ratio.
# Each tune's folder is OUT/<engine>/<scene>/ (tuned.json, <engine>.json, the paste-ready text,
# summary.json, explain.md), its output OUT/logs/<engine>-<scene>.{stdout,stderr,seconds}.
# Resumable: a row whose summary.json exists is not tuned again (FORCE=1 tunes every row again; a
# folder of a finished tune resumes from its journal, so FORCE=1 also removes it first).
# A tune that fails gives a row saying why and the table goes on. Exits 1 at the end when a tune
# failed, an <engine>.json "lacks" is not empty or a web engine's summary.json has no engine object
# (listed on stderr).
#   scripts/engine_tune_table.sh [OUT]   (default out/engine-tune-table)
# ENGINES="threejs babylon godot unity unreal bevy filament" (default) picks engines, SCENES="yard truck-town ..." scenes (default
# the yard and all six); BIN=PATH runs another shadowtune (a copy,
# so a rebuild cannot swap it mid-table; default build/release/shadowtune, builds nothing);
# TUNE_TIMEOUT=S (default 600) stops a tune after S seconds (SIGINT, then SIGKILL a minute later) and
# its row says so.
# Needs jq, node + Chromium + engines/node_modules for threejs/babylon (scripts/setup.sh) and
# ../shared/assets for the six real scenes. One tune at a time: each takes 10-90 s or more.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
engines=${ENGINES:-threejs babylon godot unity unreal bevy filament}
out=${1:-${OUT:-$root/out/engine-tune-table}}
bin=${BIN:-$root/build/release/shadowtune}
limit=${TUNE_TIMEOUT:-600}
[[ -x $bin ]] || { echo "error: $bin not built (cmake --build build/release)" >&2; exit 1; }
command -v jq >/dev/null || { echo "error: jq not found" >&2; exit 1; }
command -v timeout >/dev/null || { echo "error: timeout (coreutils) not found" >&2; exit 1; }
mkdir -p "$out/logs"
out=$(cd "$out" && pwd)

scenes=()
for s in ${SCENES:-yard truck-town dutch-ship fox living-room palm-tree-island zdm2-sauerbraten}; do
  case $s in
    yard) scenes+=("yard=presets/default.json") ;;
    *) [[ -f $root/presets/scenes/$s.json ]] || { echo "error: no presets/scenes/$s.json" >&2; exit 2; }
       scenes+=("$s=presets/scenes/$s.json") ;;
  esac
done

# jq helpers on one summary.json: a share as "x.xxx %", an error to 4 decimals, ms to 1 decimal.
pct() { jq -r "$1 | if . == null then \"-\" else . * 100 | (. * 1000 | round) / 1000 | tostring + \" %\" end" "$2"; }
num4() { jq -r "$1 | if . == null then \"-\" else (. * 10000 | round) / 10000 | tostring end" "$2"; }
ms1() { jq -r "$1 | if . == null then \"-\" else (. * 10 | round) / 10 | tostring end" "$2"; }

problems=()
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
echo "load before: $load_before" >&2
for engine in $engines; do
  case $engine in threejs|babylon|godot|unity|unreal|bevy|filament) ;;
    *) echo "error: unknown engine '$engine' (threejs, babylon, godot, unity, unreal, bevy, filament)" >&2; exit 2 ;; esac
  web=0
  [[ $engine == threejs || $engine == babylon ]] && web=1
  ref=".references[\"$engine-defaults\"]"
  rows=()
  for entry in "${scenes[@]}"; do
    scene=${entry%%=*}
    preset=$root/${entry#*=}
    dir=$out/$engine/$scene
    log=$out/logs/$engine-$scene
    if [[ ${FORCE:-0} == 1 || ! -f $dir/summary.json ]]; then
      # a folder of a finished tune would resume from its journal: start afresh
      [[ ${FORCE:-0} == 1 ]] && rm -rf "$dir"
      echo "tuning $scene for $engine ... (load $(cut -d' ' -f1 /proc/loadavg))" >&2
      rc=0
      t0=$(date +%s.%N)
      # Ctrl-C (SIGINT) first, as a user would; SIGKILL a minute later if the tune does not stop
      timeout -s INT -k 60 "$limit" "$bin" tune "$preset" --engine "$engine" --out "$dir" \
        >"$log.stdout" 2>"$log.stderr" || rc=$?
      t1=$(date +%s.%N)
      awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f\n", b - a }' >"$log.seconds"
      if [[ $rc != 0 || ! -f $dir/summary.json ]]; then
        why=$(grep -m1 -iE '^(error|fatal|terminate)|error:' "$log.stderr" || true)
        [[ -n $why ]] || why=$(grep -v '^[[:space:]]*$' "$log.stderr" | tail -1 || true)
        [[ -n $why ]] || why="nothing on stderr"
        why="exit $rc: $why"
        if [[ $rc == 124 || $rc == 137 ]]; then
          why="timed out after ${limit} s ($( ((rc == 137)) && echo "killed: SIGINT did not stop it" || echo "stopped by SIGINT"); last line: $(grep -v '^[[:space:]]*$' "$log.stderr" | tail -1 || true))"
        fi
        [[ $rc == 0 ]] && why="no summary.json ($why)"
        # a failed tune's summary.json must not count as done on the next run
        [[ -f $dir/summary.json ]] && mv "$dir/summary.json" "$dir/summary.failed.json"
        rows+=("| $scene | failed: ${why//|/\\|} | | | | | $(cat "$log.seconds") | failed |")
        problems+=("$engine $scene: tune failed: $why (log $log.stderr)")
        continue
      fi
    fi
    f=$dir/summary.json
    if ! jq -e "$ref.tuned.costMs and .tuned.tuned.costMs" "$f" >/dev/null; then
      rows+=("| $scene | failed: summary.json has no $engine-defaults reference or tuned figures | | | | | | failed |")
      problems+=("$engine $scene: summary.json has no $engine-defaults reference or tuned figures")
      continue
    fi
    notes=()
    # what the engine lacks of the tuned preset: must be empty for an engine-bound tune
    lacks=$(jq -r '.lacks // [] | map(if type == "string" then . else tojson end) | join("; ")' "$dir/$engine.json" 2>/dev/null || echo "no $engine.json")
    if [[ -n $lacks ]]; then
      notes+=("lacks: $lacks")
      problems+=("$engine $scene: $engine.json lacks is not empty: $lacks")
    fi
    if jq -e '.heldOutHolds == false' "$f" >/dev/null; then notes+=("does not hold on the held-out view"); fi
    mis=".figures[\"accuracy.misclassified\"]"
    soft=".figures[\"soft.filteredError\"]"
    defaults="$(pct "$ref.tuned$mis" "$f") / $(num4 "$ref.tuned$soft" "$f") / $(ms1 "$ref.tuned.costMs" "$f")"
    tuned="$(pct ".tuned.tuned$mis" "$f") / $(num4 ".tuned.tuned$soft" "$f") / $(ms1 ".tuned.tuned.costMs" "$f")"
    heldout="$(pct "$ref.heldOut$mis" "$f") -> $(pct ".tuned.heldOut$mis" "$f")"
    # the goal, part by part (modelled on the tuned views; the engine's own figure for web engines)
    missed=$(jq -r --arg e "$engine" --argjson web "$web" '
      def r(a; b): if b == 0 then (if a == 0 then 0 else 1e9 end) else a / b end;
      def x(v): (v * 100 | round) / 100 | tostring + "x";
      .references[$e + "-defaults"].tuned as $d | .tuned.tuned as $t
      | [ (if $t.costMs > $d.costMs then "cost \(($t.costMs * 10 | round) / 10) > \(($d.costMs * 10 | round) / 10) ms" else empty end),
          (r($t.figures["accuracy.misclassified"]; $d.figures["accuracy.misclassified"]) as $q
            | if $q > 0.5 then "misclassified " + x($q) else empty end),
          (r($t.figures["soft.filteredError"]; $d.figures["soft.filteredError"]) as $q
            | if $q > 0.5 then "soft filtered " + x($q) else empty end),
          (if $web == 1 then
             (if .engine.tuned.tuned["accuracy.misclassified"] == null then "no engine figures"
              else r(.engine.tuned.tuned["accuracy.misclassified"]; .engine.defaults.tuned["accuracy.misclassified"]) as $q
                | if $q > 0.5 then "engine misclassified " + x($q) else empty end end)
           else empty end) ]
      | join(", ")' "$f")
    goal=met
    [[ -z $missed ]] || goal="missed ($missed)"
    if ((web)); then
      if jq -e '.engine.tuned.tuned["accuracy.misclassified"] != null' "$f" >/dev/null; then
        inengine="$(pct '.engine.defaults.tuned["accuracy.misclassified"]' "$f") -> $(pct '.engine.tuned.tuned["accuracy.misclassified"]' "$f") | $(pct '.engine.tuned.tuned.agreement' "$f")"
      else
        warn=$(grep -m1 -i 'warning' "$log.stderr" 2>/dev/null || true)
        inengine="no engine object${warn:+ (${warn//|/\\|})} | -"
        problems+=("$engine $scene: summary.json has no engine object${warn:+: $warn}")
      fi
    else
      inengine="model only | model only"
    fi
    wall=$(cat "$log.seconds" 2>/dev/null || echo "-")
    search=$(jq -r '(.secondsAllRuns // .seconds) | (. * 10 | round) / 10' "$f")
    note=""
    ((${#notes[@]})) && note=" ($(IFS=';'; echo "${notes[*]}"))"
    rows+=("| $scene | $defaults | $tuned | $heldout | $inengine | $wall ($search) | $goal$note |")
  done
  version=$(jq -r '.engine.version // empty' "$out/$engine"/*/summary.json 2>/dev/null | head -1 || true)
  echo
  if ((web)); then
    echo "### $engine${version:+ $version}: its own knobs, in the engine"
  else
    echo "### $engine: its own knobs; $engine does not run here, every figure is shadowtune's model of it"
  fi
  echo
  echo "| scene | defaults (modelled): misclassified / soft filtered / cost ms | tuned (modelled) | held-out misclassified (modelled): defaults -> tuned | in the engine: misclassified defaults -> tuned | in the engine: tuned pixel agreement | seconds: wall (search) | goal |"
  echo "|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
done
echo
echo "machine: $(nproc) cores; load before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg) (rows skipped as done keep the seconds of their own run)"
if ((${#problems[@]})); then
  echo >&2
  echo "${#problems[@]} problem(s):" >&2
  printf '  %s\n' "${problems[@]}" >&2
  exit 1
fi
