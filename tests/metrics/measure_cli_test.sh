#!/usr/bin/env bash
# End-to-end checks of `shadowtune measure` as a user runs it: files, JSON, summary, exit codes.
# usage: measure_cli_test.sh SHADOWTUNE PRESET_DIR BAD_PRESET_DIR
set -uo pipefail
bin=$1 presets=$2 data=$3
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME CONDITION...: records a failure with NAME when the condition fails
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >"$work/stdout" 2>"$work/stderr"; echo $? >"$work/rc"; }
rc() { [[ $(cat "$work/rc") == "$1" ]]; }
out_has() { grep -qF -- "$1" "$work/stdout"; }
err_has() { grep -qF -- "$1" "$work/stderr"; }
json_has() { grep -qF -- "\"$2\"" "$1"; }

# A preset with a camera path: figures, images and flicker.
sed 's/"output":/"path": { "frames": 3, "keyframes": [ { "position": [0, 12, 14], "target": [0, 0, 0] }, { "position": [0.02, 12, 14], "target": [0.02, 0, 0] } ] },\n  "output":/' \
  "$presets/box-over-plane.json" >"$work/with-path.json"
run measure "$work/with-path.json" --out "$work/out" --size 96x64 --frames 1
check "good preset exits 0" rc 0
check "one summary line names the preset and timings" out_has "with-path: 96x64 misclassified"
check "summary has the ground truth time" out_has "ground truth"
check "summary has the soft truth and its time" out_has "against the sun's disc (0.53 deg, 16 rays)"
check "summary has the soft truth time" out_has ", soft truth "
for f in metrics.json truth.png errors.png artifacts.png texel-density.png flicker.png path.png; do
  check "writes $f" test -s "$work/out/with-path/$f"
done
m="$work/out/with-path/metrics.json"
for key in misclassified falseShadow falseLight gross filteredError texelDensity p95 aliasingShare flipRate \
           meanHardStdDev gpuShadowMs shadowMapBytes texelsCovered groundTruthMs totalMs \
           soft angularDiameter sunRays acne lightBleeding peterPanning missingCaster penumbraWidth softTruthMs; do
  check "metrics.json has $key" json_has "$m" "$key"
done
check "truth image has the size" bash -c "oiiotool --info '$work/out/with-path/truth.png' | grep -q '96 x   64'"
check "errors.png has its legend under the image" bash -c "oiiotool --info '$work/out/with-path/errors.png' | grep -qE '96 x +[0-9]{3}'"
check "no temporary files left" bash -c "! ls -A '$work/out/with-path' | grep -q tmp"

# A bad preset is reported and skipped; the good one is still measured.
run measure "$data/bad-count.json" "$presets/box-over-plane.json" --out "$work/mixed" --size 64x48 --frames 1
check "mixed run exits 1" rc 1
check "bad preset names file and field" err_has "bad-count.json: cascades.count: must be in 1..8, got 12"
check "good preset still measured" test -s "$work/mixed/box-over-plane/metrics.json"
check "no flicker image without a path" test ! -e "$work/mixed/box-over-plane/flicker.png"
check "no path chart without a path" test ! -e "$work/mixed/box-over-plane/path.png"

# The shipped default preset has a path: its chart of flip share and misclassification per frame.
run measure "$presets/default.json" --out "$work/default" --size 96x64 --frames 1
check "default preset exits 0" rc 0
check "default writes path.png" test -s "$work/default/default/path.png"
check "path.png is a 1200x900 chart" bash -c "oiiotool --info '$work/default/default/path.png' | grep -q '1200 x  900'"

# Presets after one with a path: its chart's Pango fonts stay alive, and freeing the text caches
# for the next preset's legends used to abort (cairo's static-data assertion, exit 134).
run measure "$work/with-path.json" "$presets/box-over-plane.json" "$work/with-path.json" --out "$work/after-path" \
  --size 64x48 --frames 1
check "presets after one with a path exit 0" rc 0
check "... and the next preset's legends are drawn" test -s "$work/after-path/box-over-plane/errors.png"

run measure "$presets/box-over-plane.json" --out "$work/x" --size 10x10000
check "bad size rejected" bash -c "[[ \$(cat '$work/rc') == 2 ]] && grep -qF -- '--size' '$work/stderr'"

echo "$failures failed"
[[ $failures == 0 ]]
