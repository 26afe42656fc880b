#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): how well the shipped cost profile's modelled frame
# cost follows the measured GPU time on the shipped sweeps' points (every EVERY-th point of each
# presets/sweeps/*.json, each timed over FRAMES frames with every map redrawn, after an untimed
# warm-up frame, in PASSES passes over all the points whose frames are joined: this machine's
# speed drifts by 10-20 % over minutes, and a minimum over passes spread in time drifts less). Prints the machine and the load, one tab-separated line per point (sweep, point,
# model ms, measured min ms, measured median ms), then the median |model - measured| / measured
# and Spearman's rank correlation, against the minimum and the median of the frames.
# Goal (issue 18): median error <= 15 %, Spearman >= 0.95, at low load. docs/cost-model.md says
# where the model is known to be wrong.
#   scripts/bench_cost_model.sh [BUILD_DIR] [EVERY] [FRAMES] [PROFILE] [PASSES]   scenes need ../shared/assets
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
every=${2:-7}
frames=${3:-5}
profile=${4:-$root/presets/cost-profiles/llvmpipe.json}
passes=${5:-3}
echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores"
echo "load before: $(uptime)"
cd "$root"
# A sweep file that does not load is reported and skipped (exit 1): the figures of the others stand.
status=0
EGL_PLATFORM=surfaceless "$build/shadowtune" calibrate --check presets/sweeps/*.json --every "$every" \
  --frames "$frames" --passes "$passes" --profile "$profile" || status=$?
echo "load after: $(uptime)"
exit "$status"
