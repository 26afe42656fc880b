#!/usr/bin/env bash
# `tune --engine bevy|filament|unity|unreal` (issue "Tune for your engine"), on the yard at 160x90
# with a short search. None of them runs here, so the figures are the model's (docs/engines.md
# "Bevy", "Filament", "Unity URP", "Unreal Engine 5"); the test holds:
#   - the budget is the engine defaults' modelled cost (a reference named ENGINE-defaults);
#   - the tune never emits a setting the engine lacks (ENGINE.json "lacks" is empty);
#   - summary.json claims no figures measured in the engine (engine null);
#   - the paste-ready text parses back, by a reader of the engine's own syntax written here (Rust
#     struct literals `name: value,` in bevy.rs; `options.name = value;` in filament.cpp; the asset's
#     `  m_Name: value` YAML lines in unity-urp.asset; `r.X=value` cvars in unreal-engine.ini and
#     `set_editor_property('snake_name', value)` in unreal-light.py), to exactly the knobs of ENGINE.json.
# Usage: tune_model_engine_test.sh ENGINE SHADOWTUNE SOURCE_DIR WORK_DIR
set -euo pipefail
engine=$1
st=$2
src=$3
work=$4
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "tune_model_engine_test ($engine): FAIL: $*" >&2
  exit 1
}
case $engine in
  bevy) text=bevy.rs ;;
  filament) text=filament.cpp ;;
  unity) text=unity-urp.asset ;;
  unreal) text=unreal-light.py ;;
  *) fail "no reader for $engine" ;;
esac
out=$work/tune
"$st" tune "$src/presets/default.json" --engine "$engine" --size 160x90 --evaluations 8 --views 2 --out "$out" >"$work/tune.log" 2>&1 ||
  fail "tune exited $? ($(tail -3 "$work/tune.log"))"
grep -q "reference $engine-defaults:" "$work/tune.log" || fail "the budget is not the $engine defaults'"
[[ -s $out/$engine.json && -s $out/$text && -s $out/tuned.json && -s $out/summary.json ]] || fail "outputs missing"
jq -e '.engine == null' "$out/summary.json" >/dev/null || fail "summary.json claims figures measured in $engine, which does not run here"
[[ $(jq '.lacks | length' "$out/$engine.json") == 0 ]] || fail "the tune used knobs $engine lacks: $(jq -c .lacks "$out/$engine.json")"

# The engine's text back to JSON, one "key": value line each (numbers lose a C++ `f` suffix).
if [[ $engine == bevy ]]; then
  {
    sed -nE 's/^ *(shadow_depth_bias|shadow_normal_bias|overlap_proportion|minimum_distance): ([-0-9.eE+]+),$/"\1": \2,/p' "$out/$text"
    sed -nE 's/.*DirectionalLightShadowMap \{ size: ([0-9]+) \}.*/"shadow_map_size": \1,/p' "$out/$text"
    sed -nE 's/^ *bounds: vec!\[([-0-9.eE+, ]*)\],$/"bounds": [\1],/p' "$out/$text"
    sed -nE 's/.*ShadowFilteringMethod::([A-Za-z0-9]+)\).*/"shadow_filtering_method": "\1",/p' "$out/$text"
  } >"$work/fields"
elif [[ $engine == unity ]]; then
  # the asset's YAML lines: `  m_Name: 1.5`, vectors as {x: a, y: b, z: c}
  sed -nE 's/^  (m_[A-Za-z0-9]+): ([-0-9.eE+]+)$/"\1": \2,/p; s/^  (m_[A-Za-z0-9]+): \{(.*)\}$/"\1": [\2],/p' "$out/$text" |
    sed -E 's/[xyzw]: //g' >"$work/fields"
elif [[ $engine == unreal ]]; then
  # [SystemSettings] cvars `r.X=5`, and set_editor_property('snake_name', value) back in UE's CamelCase
  sed -nE 's/^(r\.[A-Za-z.]+)=([-0-9.eE+]+)$/"\1": \2,/p' "$out/unreal-engine.ini" | grep -v Virtual >"$work/fields"
  sed -nE "s/.*set_editor_property\('([a-z_]+)', ([-0-9.eE+]+)\)$/\1 \2/p" "$out/$text" |
    while read -r name value; do
      camel=$(echo "$name" | sed -E 's/(^|_)([a-z])/\U\2/g')
      echo "\"$camel\": $value,"
    done >>"$work/fields"
else
  {
    sed -nE 's/^options\.([A-Za-z]+) = ([-0-9.eE+]+)f?;$/"\1": \2,/p; s/^options\.([A-Za-z]+) = (true|false);$/"\1": \2,/p' "$out/$text"
    echo "\"cascadeSplitPositions\": [$(sed -nE 's/^options\.cascadeSplitPositions\[[0-2]\] = ([-0-9.eE+]+)f;$/\1/p' "$out/$text" | paste -sd,)],"
    sed -nE 's/.*setShadowType\(View::ShadowType::([A-Z]+)\);.*/"shadowType": "\1",/p' "$out/$text"
  } >"$work/fields"
fi
sed '$ s/,$//' "$work/fields" | { echo '{'; cat; echo '}'; } >"$work/parsed.json"
jq -S . "$work/parsed.json" >"$work/parsed.sorted.json" || fail "the pasted text did not read as fields: $(cat "$work/parsed.json")"
jq -S '.knobs' "$out/$engine.json" >"$work/knobs.sorted.json"
diff -u "$work/knobs.sorted.json" "$work/parsed.sorted.json" >&2 || fail "the pasted text does not parse back to $engine.json's knobs"
[[ $(jq 'keys | length' "$work/parsed.sorted.json") -ge 7 ]] || fail "the pasted text holds too few knobs"
echo "tune_model_engine_test ($engine): ok ($(jq -c .knobs "$out/$engine.json"))"
