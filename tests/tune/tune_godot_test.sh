#!/usr/bin/env bash
# `tune --engine godot` (issue "Tune for your engine"), on the yard at 160x90 with a short search.
# Godot does not run here, so its figures are the model's (docs/engines.md "Godot 4"); the test holds:
#   - the budget is the Godot defaults' modelled cost (a reference named godot-defaults);
#   - the tune never emits a setting Godot lacks (godot.json "lacks" is empty);
#   - the paste-ready text parses back, by a reader of Godot's own line formats written here
#     (`key = value` under the light's node in a .tscn; `key=value` under [rendering] in
#     project.godot), to exactly the knobs of godot.json;
# Usage: tune_godot_test.sh SHADOWTUNE SOURCE_DIR WORK_DIR
set -euo pipefail
st=$1
src=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "tune_godot_test: FAIL: $*" >&2
  exit 1
}
out=$work/tune
"$st" tune "$src/presets/default.json" --engine godot --size 160x90 --evaluations 8 --views 2 --out "$out" >"$work/tune.log" 2>&1 ||
  fail "tune exited $? ($(tail -3 "$work/tune.log"))"
grep -q "reference godot-defaults:" "$work/tune.log" || fail "the budget is not the Godot defaults'"
[[ -s $out/godot.json && -s $out/godot-light.tscn && -s $out/godot-project.godot && -s $out/tuned.json ]] || fail "outputs missing"
jq -e '.engine == null' "$out/summary.json" >/dev/null || fail "summary.json claims figures measured in Godot, which does not run here"
[[ $(jq '.lacks | length' "$out/godot.json") == 0 ]] || fail "the tune used knobs Godot lacks: $(jq -c .lacks "$out/godot.json")"

# Godot's text back to JSON: every value in these files is a JSON scalar (true, 0.1, 4096).
{
  grep -v '^;' "$out/godot-light.tscn" | grep -E '^[a-z_0-9]+ = ' | sed -E 's/^([a-z_0-9]+) = (.*)$/"\1": \2,/'
  awk '/^\[rendering\]/ {on = 1; next} /^\[/ {on = 0} on && /=/' "$out/godot-project.godot" |
    sed -E 's#^([^=]+)=(.*)$#"rendering/\1": \2,#'
} | sed '$ s/,$//' | { echo '{'; cat; echo '}'; } >"$work/parsed.json"
jq -S . "$work/parsed.json" >"$work/parsed.sorted.json" || fail "the pasted text is not key = value lines: $(cat "$work/parsed.json")"
jq -S '.knobs + {"shadow_enabled": true}' "$out/godot.json" >"$work/knobs.sorted.json"
diff -u "$work/knobs.sorted.json" "$work/parsed.sorted.json" >&2 || fail "the pasted text does not parse back to godot.json's knobs"
[[ $(jq 'keys | length' "$work/parsed.sorted.json") -ge 14 ]] || fail "the pasted text holds too few knobs"
echo "tune_godot_test: ok ($(jq -c .knobs "$out/godot.json"))"
