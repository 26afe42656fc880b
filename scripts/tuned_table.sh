#!/usr/bin/env bash
# docs/tuning.md's table of tuned presets, from the folders scripts/tune_all.sh leaves: per scene
# and reference, the reference's and the tuned preset's misclassified share, soft filtered error
# and modelled cost on the tuned views, both errors on the held-out view, the evaluations and the
# wall-clock time of the tune (of all its runs, when it was resumed). "goal" is the issue's: no more modelled cost and at most half the
# reference's error, misclassified and soft filtered both. "knobs the engine lacks" (engine
# references): the noEquivalent items of `shadowtune export presets/tuned/<run>.json --to <engine>
# --json` that are the preset's own, named in parentheses (the engine settings listed there with
# their defaults kept, e.g. Unity's unused cascade3Split, are not); a row naming any is a tune at
# the engine's budget, not settings the engine can take. "—" for a seed reference, "not exported"
# without BUILD_DIR/shadowtune or the tuned preset.
#   scripts/tuned_table.sh [OUT] [BUILD_DIR]   (default out/tuned-runs, build/release)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/tuned-runs}
build=${2:-$root/build/release}
echo "| scene as reference | reference: misclassified / soft filtered / cost | tuned: misclassified / soft filtered / cost | held-out misclassified: reference -> tuned | evaluations | time | goal | knobs the engine lacks |"
echo "|---|---|---|---|---|---|---|---|"
for summary in "$out"/*/summary.json; do
  run=$(basename "$(dirname "$summary")")
  reference=${run##*-at-} reference=${reference%-budget} preset=$root/presets/tuned/$run.json
  case $reference in
    unreal | unity | godot | bevy | filament | threejs | babylon)
      if [ -x "$build/shadowtune" ] && [ -f "$preset" ]; then
        lacks=$("$build/shadowtune" export "$preset" --to "$reference" --json | jq -r '
          [.noEquivalent[].name | select(startswith("(")) | ltrimstr("(") | rtrimstr(")")]
          | if length == 0 then "none" else join(", ") end') || lacks="export failed"
      else lacks="not exported"; fi ;;
    *) lacks="—" ;;
  esac
  jq -r --arg run "$run" --arg lacks "$lacks" '
    def pct: . * 100 | (. * 1000 | round) / 1000 | tostring + " %";
    def num: (. * 10000 | round) / 10000 | tostring;
    def ms: (. * 10 | round) / 10 | tostring + " ms";
    (.references | to_entries[0].value) as $r
    | $r.tuned.figures as $rf | .tuned.tuned.figures as $tf
    | ($tf["cost.modelMs"] <= $rf["cost.modelMs"] + 1e-9
       and $tf["accuracy.misclassified"] <= 0.5 * $rf["accuracy.misclassified"]
       and $tf["soft.filteredError"] <= 0.5 * $rf["soft.filteredError"]) as $goal
    | "| \($run) | \($rf["accuracy.misclassified"] | pct) / \($rf["soft.filteredError"] | num) / \($rf["cost.modelMs"] | ms) "
      + "| \($tf["accuracy.misclassified"] | pct) / \($tf["soft.filteredError"] | num) / \($tf["cost.modelMs"] | ms) "
      + "| \(if $r.heldOut then ($r.heldOut.figures["accuracy.misclassified"] | pct) + " -> " + (.tuned.heldOut.figures["accuracy.misclassified"] | pct) else "-" end) "
      + "| \(.search.evaluations) (best at \(if .search.keptEarlier then "an earlier run" else .search.evaluationsToBest end)) | \((.secondsAllRuns // .seconds) | round) s | \(if $goal then "met" else "missed" end) | \($lacks) |"' "$summary"
done
