#!/usr/bin/env bash
# `calibrate`: bad options and a malformed profile are refused with the reason (the JSON path for
# the profile) and a non-zero exit; --check times a sweep's points and prints, per point, the
# modelled and measured frame cost, then the summary with the point count.
# usage: calibrate_cli_test.sh SHADOWTUNE PRESET_DIR
set -uo pipefail
bin=$1 presets=$2
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
check() {
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >"$work/stdout" 2>"$work/stderr"; echo $? >"$work/rc"; }
rc() { [[ $(cat "$work/rc") == "$1" ]]; }
err_has() { grep -qF -- "$1" "$work/stderr"; }
out_has() { grep -qE -- "$1" "$work/stdout"; }

run calibrate --size 10x10
check "bad --size exits 2" rc 2
check "bad --size names the option" err_has "error: --size: expected WxH"

sed 's/"fragments": [0-9.e+-]*/"fragments": "many"/' "$presets/cost-profiles/llvmpipe.json" >"$work/bad.json"
cat >"$work/two.json" <<JSON
{"version": 1, "base": "$presets/box-over-plane.json", "set": {"output.width": 64, "output.height": 36},
 "axes": [{"field": "cascades.count", "values": [1, 2]}]}
JSON
run calibrate --check "$work/two.json" --profile "$work/bad.json" --frames 1
check "malformed profile exits 1" rc 1
check "malformed profile error names file and JSON path" \
  err_has "$work/bad.json: passes.cascade.coefficients.fragments: expected a number, got string"

run calibrate --check "$work/two.json" --profile "$presets/cost-profiles/llvmpipe.json" --frames 1
check "--check exits 0" rc 0
check "--check prints one line per point" out_has $'^two\tcount=2\t[0-9.]+\t[0-9.]+\t[0-9.]+$'
check "--check prints the summary" out_has "^sweep points against llvmpipe.*: 2 frames; median"

run calibrate --refit main
check "--refit of a jointly fitted kind exits non-zero" test "$(cat "$work/rc")" != 0
check "--refit of a jointly fitted kind says why" err_has "fitted jointly on frame totals"

base=$presets/cost-profiles/llvmpipe.json
# The calibration set is read from the presets folder of the working directory.
(cd "$presets/.." && run calibrate --refit depthBounds --frames 1 --size 64x36 --out "$work/refit.json")
check "--refit exits 0" rc 0
check "--refit prints a line per depth-bounds point" \
  out_has $'^depthBounds\ttruck-town depthBounds=fit\t[0-9.]+\t[0-9.]+\t[0-9.]+$'
check "--refit records where the kind was fitted" grep -q '"calibrated": ' "$work/refit.json"
section() { sed -n "/\"$1\": {/,/}/p" "$2"; }
check "--refit keeps the cascade coefficients" diff <(section cascade "$base") <(section cascade "$work/refit.json")
check "--refit keeps the main coefficients" diff <(section main "$base") <(section main "$work/refit.json")
run calibrate --check "$work/two.json" --profile "$work/refit.json" --frames 1
check "the refitted profile loads" rc 0

echo "$failures failure(s)"
((failures == 0))
