#!/usr/bin/env bash
# End-to-end checks of `shadowtune export`: exit codes, messages and both output forms.
# usage: export_cli_test.sh SHADOWTUNE PRESET_DIR DATA_DIR
set -uo pipefail
bin=$1 presets=$2 data=$3
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check NAME CONDITION...
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >"$work/stdout" 2>"$work/stderr"; echo $? >"$work/rc"; }
rc() { [[ $(cat "$work/rc") == "$1" ]]; }
err_has() { grep -qF -- "$1" "$work/stderr"; }
out_has() { grep -qF -- "$1" "$work/stdout"; }

for engine in godot unity unreal bevy threejs filament babylon; do
  run export "$presets/engines/$engine.json" --to "$engine"
  check "$engine: exits 0" rc 0
  check "$engine: three groups" bash -c "grep -qx 'exact:' '$work/stdout' && grep -qx 'approximated:' '$work/stdout' && grep -qx 'no equivalent:' '$work/stdout'"
done
run export "$presets/engines/godot.json" --to godot
check "godot text names split_1" out_has "directional_shadow_split_1 = 0.1"

run export "$presets/default.json" --to unreal --json
check "--json exits 0" rc 0
check "--json is JSON with the groups" python3 -c "import json,sys; j=json.load(open('$work/stdout')); sys.exit(0 if j['engine']=='unreal' and all(k in j for k in ('exact','approximated','noEquivalent')) else 1)"

# The knob table's part: the engine's own preset takes its knobs whole, and --paste writes the
# knobs as --json prints them with the paste-ready text beside them.
run export "$presets/engines/unity.json" --to unity --json --paste "$work/paste"
check "--paste exits 0" rc 0
check "unity's own preset lacks nothing" python3 -c "import json,sys; j=json.load(open('$work/stdout')); sys.exit(0 if j['lacks']==[] and j['knobs']['m_ShadowCascadeCount']==1 else 1)"
check "--paste writes unity.json with the printed knobs" python3 -c "import json,sys; a=json.load(open('$work/stdout')); b=json.load(open('$work/paste/unity.json')); sys.exit(0 if a['knobs']==b['knobs'] else 1)"
check "--paste writes the asset's lines" grep -q '^  m_ShadowDistance: 50' "$work/paste/unity-urp.asset"
run export "$presets/default.json" --to unreal
check "what unreal lacks of the yard is listed" out_has "a constant bias per cascade other than its texel"

run export "$presets/default.json" --to cryengine
check "unknown engine exits 2" rc 2
check "unknown engine lists the valid ones" err_has "unknown engine 'cryengine'; expected one of: godot, unity, unreal, bevy, threejs, filament, babylon"

run export "$data/bad-count.json" --to godot
check "invalid preset exits 1" rc 1
check "invalid preset names file and field" err_has "bad-count.json: cascades.count: must be in 1..8, got 12"
check "invalid preset prints nothing" bash -c "[[ ! -s '$work/stdout' ]]"

run export "$work/missing.json" --to bevy
check "missing preset exits 1" rc 1
check "missing preset is named" err_has "missing.json"

run export "$presets/default.json"
check "missing --to is refused" bash -c "[[ \$(cat '$work/rc') != 0 ]] && grep -q -- '--to' '$work/stderr'"

echo "$failures failed"
[[ $failures == 0 ]]
