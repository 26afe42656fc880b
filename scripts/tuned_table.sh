#!/usr/bin/env bash
# docs/tuning.md's table of tuned presets, from the folders scripts/tune_all.sh leaves: per scene
# and reference, the reference's and the tuned preset's misclassified share, soft filtered error
# and modelled cost on the tuned views, both errors on the held-out view, the evaluations and the
# wall-clock time of the tune (of all its runs, when it was resumed). "goal" is the issue's: no more modelled cost and at most half the
# reference's error, misclassified and soft filtered both.
#   scripts/tuned_table.sh [OUT]   (default out/tuned-runs)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/tuned-runs}
echo "| scene as reference | reference: misclassified / soft filtered / cost | tuned: misclassified / soft filtered / cost | held-out misclassified: reference -> tuned | evaluations | time | goal |"
echo "|---|---|---|---|---|---|---|"
for summary in "$out"/*/summary.json; do
  run=$(basename "$(dirname "$summary")")
  jq -r --arg run "$run" '
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
      + "| \(.search.evaluations) (best at \(if .search.keptEarlier then "an earlier run" else .search.evaluationsToBest end)) | \((.secondsAllRuns // .seconds) | round) s | \(if $goal then "met" else "missed" end) |"' "$summary"
done
