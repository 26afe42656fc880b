#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): one tune of truck-town at ogldev-49's modelled
# budget, as issue 19's "done when" states it. Prints the machine and the load, the wall-clock
# time of the whole tune, the median time per evaluation and its split (render and read-back,
# truth, soft truth), the search's counts, and the tuned preset's figures against the input's and
# the reference's on the tuned and held-out views. Goal (issue 19): <= 0.15 s per evaluation and
# <= 3 minutes per tune on the 2-core CI machine; misclassified <= 0.40 % on the tuned views.
#   scripts/bench_tune.sh [BUILD_DIR] [EVALUATIONS] [OUT_DIR]   needs ../shared/assets
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
evaluations=${2:-60}
out=${3:-$(mktemp -d)/tune}
echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores"
echo "load before: $(uptime)"
cd "$root"
start=$(date +%s.%N)
EGL_PLATFORM=surfaceless "$build/shadowtune" tune presets/scenes/truck-town.json --budget-from presets/ogldev-49.json \
  --evaluations "$evaluations" --out "$out" 2>&1 | grep -v '^tune \['
end=$(date +%s.%N)
echo "load after: $(uptime)"
echo "whole tune: $(echo "$end - $start" | bc) s wall-clock"
jq -r '"per evaluation: median \(.timing.medianMsPerEvaluation | floor) ms over \(.timing.evaluationsMeasured) measured; per view \(.timing.meanMsPerViewMeasurement | floor) ms (render and read-back \(.timing.meanRenderAndReadBackMs | floor), truth \(.timing.meanTruthMs | floor), soft truth \(.timing.meanSoftTruthMs | floor))",
       "search: \(.search.evaluations) evaluations (best found at \(.search.evaluationsToBest)), \(.search.screenings) screenings, \(.search.screenedOut) screened out",
       "misclassified on the tuned views: input \(.input.tuned.figures["accuracy.misclassified"] * 100) %, tuned \(.tuned.tuned.figures["accuracy.misclassified"] * 100) %, ogldev-49 \(.references["ogldev-49"].tuned.figures["accuracy.misclassified"] * 100) %",
       "misclassified on the held-out views: input \(.input.heldOut.figures["accuracy.misclassified"] * 100) %, tuned \(.tuned.heldOut.figures["accuracy.misclassified"] * 100) %, ogldev-49 \(.references["ogldev-49"].heldOut.figures["accuracy.misclassified"] * 100) %",
       "modelled cost: tuned \(.tuned.tuned.costMs) ms, budget \(.budgetMs) ms; holds on held-out views: \(.heldOutHolds)"' "$out/summary.json"
echo "output: $out"
