#!/usr/bin/env bash
# End-to-end checks of `shadowtune render` as a user runs it: exit codes, messages, files.
# usage: cli_test.sh SHADOWTUNE PRESET_DIR DATA_DIR
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
rc_nonzero() { [[ $(cat "$work/rc") != 0 ]]; }
err_has() { grep -qF -- "$1" "$work/stderr"; }
out_has() { grep -qF -- "$1" "$work/stdout"; }

# A good preset: image of the requested size and statistics with one entry per cascade.
run render "$presets/box-over-plane.json" --out "$work/good" --size 64x48
check "good preset exits 0" rc 0
check "one line per image" out_has "wrote $work/good/box-over-plane.png (64x48"
check "png has the requested size" bash -c "oiiotool --info '$work/good/box-over-plane.png' | grep -q '64 x   48'"
check "stats list both cascades" bash -c "[[ \$(grep -c '\"texelWorldSize\"' '$work/good/box-over-plane.json') == 2 ]]"
check "no temporary files left" bash -c "! ls -A '$work/good' | grep -q tmp"

# A bad value: message names the file, the JSON path and the reason; nothing is written.
run render "$data/bad-count.json" --out "$work/bad"
check "bad count exits non-zero" rc_nonzero
check "bad count names file and field" err_has "bad-count.json: cascades.count: must be in 1..8, got 12"
check "bad count writes no image" bash -c "! ls '$work/bad'/*.png 2>/dev/null"

run render "$data/bad-several.json" --out "$work/bad"
check "all problems reported: mapSize" err_has "cascades.mapSize"
check "all problems reported: lambda" err_has "cascades.lambda"
check "all problems reported: near/far" err_has "camera.nearPlane"
check "all problems reported: unknown key" err_has "colour: unknown key"

run render "$data/bad-syntax.json" --out "$work/bad"
check "invalid JSON gives line and column" bash -c "grep -qE 'bad-syntax.json:[0-9]+:[0-9]+: invalid JSON' '$work/stderr'"

# Good and bad together: the good one is written, the bad one skipped, exit code 1.
run render "$presets/box-over-plane.json" "$data/bad-count.json" --out "$work/mixed" --size 32x32
check "mixed run exits 1" rc 1
check "mixed run still writes the good image" test -s "$work/mixed/box-over-plane.png"
check "mixed run reports the skip" err_has "skipped $data/bad-count.json"

# The schema is not in presets/ (so presets/*.json never picks it up); given as a preset, it fails.
check "presets/ holds no schema" bash -c "! grep -l json-schema.org '$presets'/*.json '$presets'/scenes/*.json"
run render "$presets/../schema/preset.schema.json" "$presets/box-over-plane.json" --out "$work/schema" --size 32x32
check "the schema as a preset exits 1" rc 1
check "the schema as a preset says what it is" err_has "makes this a JSON Schema, not a preset"
check "the schema writes no image" bash -c "! ls '$work/schema'/preset.schema* 2>/dev/null"
check "the preset beside it is still written" test -s "$work/schema/box-over-plane.png"

run render "$work/does-not-exist.json" --out "$work/x"
check "missing preset exits non-zero" rc_nonzero
check "missing preset is named" err_has "does-not-exist.json"
run render "$presets" --out "$work/x"
check "a directory as preset exits non-zero" rc_nonzero
check "a directory as preset is named" err_has "$presets"

touch "$work/file" && run render "$presets/box-over-plane.json" --out "$work/file/sub"
check "unusable output folder exits non-zero" rc_nonzero
check "unusable output folder is named" err_has "$work/file/sub"

run render "$presets/box-over-plane.json" --out "$work/x" --view nonsense
check "unknown view rejected" err_has "unknown view 'nonsense'"
run render "$presets/box-over-plane.json" --out "$work/x" --size 10x10000
check "bad size rejected" err_has "--size"

echo "$failures failed"
[[ $failures == 0 ]]
