#!/usr/bin/env bash
# `tune --engine bevy|filament` (issue "Tune for your engine"), on the yard at 160x90 with a short
# search. Neither engine runs here, so the figures are the model's (docs/engines.md "Bevy",
# "Filament"); the test holds:
#   - the budget is the engine defaults' modelled cost (a reference named ENGINE-defaults);
#   - the tune never emits a setting the engine lacks (ENGINE.json "lacks" is empty);
#   - summary.json claims no figures measured in the engine (engine null);
#   - the paste-ready text parses back, by a reader of the engine's own syntax written here (Rust
#     struct literals `name: value,` in bevy.rs; `options.name = value;` in filament.cpp), to
#     exactly the knobs of ENGINE.json.
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
