#!/usr/bin/env bash
# Every command that takes a file, run from the file's own folder with its bare name ("mine.json",
# not "./mine.json"): a bare name has an empty parent path, which std::filesystem::absolute
# refused ("cannot make absolute path: Invalid argument []", issue 20). Relative references
# inside the files (a sweep's base, a preset's scene) start from that folder.
# usage: bare_name_cli_test.sh SHADOWTUNE PRESET_DIR
set -uo pipefail
bin=$1 presets=$2
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
check() {  # check NAME CONDITION...: records a failure with NAME when the condition fails
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >stdout 2>stderr; echo $? >rc; }
rc0() {
  [[ $(cat rc) == 0 ]] && ! grep -q "filesystem error" stderr && return 0
  sed 's/^/  stderr: /' stderr >&2
  return 1
}

# Small and quick: a builtin scene at 48x32, one timed frame.
cat >base.json <<'JSON'
{"version": 1, "scene": "builtin:box-over-plane", "filter": {"kind": "hard"},
 "camera": {"position": [0, 8, 10], "target": [0, 0, 0], "farPlane": 60}, "output": {"width": 48, "height": 32}}
JSON
sed 's/"hard"/"pcf2x2"/' base.json >other.json
cat >mine.json <<'JSON'
{"version": 1, "base": "base.json", "axes": [{"field": "cascades.count", "values": [1, 2]}]}
JSON
cp "$presets/cost-profiles/llvmpipe.json" profile.json

run render base.json --out r --profile profile.json
check "render base.json exits 0" rc0
check "render base.json writes its image" test -s r/base.png

run measure base.json --out m --no-flicker --frames 1 --profile profile.json
check "measure base.json exits 0" rc0
check "measure base.json writes its figures" test -s m/base/metrics.json

run sweep mine.json --out o --frames 1 --profile profile.json
check "sweep mine.json exits 0" rc0
check "sweep mine.json measures both points" bash -c "[[ \$(ls o/points | wc -l) -eq 2 ]]"
check "sweep mine.json records its folder without a trailing ." \
  bash -c "[[ \$(jq -r .presetDir o/sweep.json) == '$(pwd -P)' || \$(jq -r .presetDir o/sweep.json) == '$PWD' ]]"

run compare base.json other.json --out c --frames 1
check "compare base.json other.json exits 0" rc0
check "compare writes compare.json" test -s c/compare.json

run export base.json --to godot
check "export base.json exits 0" rc0
check "export prints the settings" grep -q "Godot" stdout

run calibrate --check mine.json --frames 1 --profile profile.json
check "calibrate --check mine.json exits 0" rc0
check "calibrate --check times both points" grep -q "mine.*count=2" stdout

exit $((failures > 0))
