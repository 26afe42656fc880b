#!/usr/bin/env bash
# engine-check end to end on the yard at 320x180 (docs/engines.md): the real three.js in headless
# Chromium against shadowtune's model of the same knobs.
#   1. three.js's defaults, Babylon.js's with a bias of 0.001, and Babylon.js's defaults, whose 5e-5
#      bias covers the yard in acne (43 % misclassified): the engine and the model agree on >= 99 % of
#      the scored pixels and their misclassified shares are within 0.3 percentage points;
#   2. the same with the model wrong, each in one method: three.js's caster faces (both instead of
#      back), Babylon's acne drawn on llvmpipe's own sub-pixel grid instead of SwiftShader's 1/16
#      (--subpixel-bits 0), and its slice corners exact instead of through the float32 inverse: the
#      agreement falls below the bar each time, so the check can fail;
#   3. usage errors exit 2 with a message and write nothing: an unknown knob, a missing engines folder.
# Usage: engine_check_test.sh SHADOWTUNE PRESETS_DIR
set -euo pipefail
st=$1
presets=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowtune-engine-check.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() {
  echo "engine_check_test: FAIL: $*" >&2
  exit 1
}

figure() { jq -r "$1" "$2/figures.json"; }

# check ENGINE OUT [extra args]: runs engine-check on the yard (the engine's defaults unless --knobs).
check() {
  local engine=$1 out=$2
  shift 2
  local knobs=(--defaults)
  [[ $engine == babylon-bias ]] && engine=babylon knobs=(--knobs "$work/babylon-bias.json")
  "$st" engine-check "$presets/default.json" --engine "$engine" "${knobs[@]}" --size 320x180 --out "$out" "$@" ||
    fail "engine-check $engine exited $? ($(tail -3 "$out/engine.log" 2>/dev/null))"
  for f in engine.png model.png truth.png disagreement.png figures.json model.json job.json; do
    [[ -s $out/$f ]] || fail "$engine: $f missing"
  done
}

echo '{"bias": 0.001}' >"$work/babylon-bias.json"
for engine in threejs babylon-bias babylon; do
  check "$engine" "$work/$engine"
  agree=$(figure .agreement "$work/$engine")
  me=$(figure '.engine.figures."accuracy.misclassified"' "$work/$engine")
  mm=$(figure '.model.figures."accuracy.misclassified"' "$work/$engine")
  scored=$(figure .scoredPixels "$work/$engine")
  echo "$engine on the yard: agreement $agree over $scored px, misclassified engine $me model $mm"
  (( scored > 30000 )) || fail "$engine: only $scored scored pixels"
  [[ $(echo "$agree >= 0.99" | bc -l) == 1 ]] || fail "$engine: agreement $agree < 0.99"
  diff=$(echo "d = $me - $mm; if (d < 0) d = -d; d" | bc -l)
  [[ $(echo "$diff <= 0.003" | bc -l) == 1 ]] || fail "$engine: misclassified differ by $diff (> 0.3 pp)"
done

# wrong ENGINE WHAT ARGS...: the model wrong in one method must fall below the bar.
wrong() {
  local engine=$1 what=$2
  shift 2
  check "$engine" "$work/wrong" "$@"
  local agree
  agree=$(figure .agreement "$work/wrong")
  echo "$engine defaults against a model with $what: agreement $agree"
  [[ $(echo "$agree < 0.99" | bc -l) == 1 ]] || fail "a model with $what still agrees ($agree)"
}
wrong threejs "both faces casting" --model-set 'cascades.casterFaces="both"'
wrong babylon "llvmpipe's sub-pixel grid" --subpixel-bits 0
wrong babylon "exact slice corners" --model-set 'cascades.sliceCorners="exact"'

set +e
"$st" engine-check "$presets/default.json" --engine threejs --knobs <(echo '{"cascade": 3}') --out "$work/bad" 2>"$work/err"
code=$?
set -e
[[ $code == 2 ]] || fail "an unknown knob exited $code, not 2"
grep -q "settings.cascade: the engine has no such knob" "$work/err" || fail "unknown knob: $(cat "$work/err")"
[[ ! -e $work/bad ]] || fail "an unknown knob left $work/bad behind"
set +e
"$st" engine-check "$presets/default.json" --engine threejs --engines-dir "$work/none" --out "$work/bad" 2>"$work/err"
code=$?
set -e
[[ $code == 2 ]] || fail "a missing engines folder exited $code, not 2"
grep -q "run.mjs is missing" "$work/err" || fail "missing engines folder: $(cat "$work/err")"
echo "engine_check_test: ok"
