#!/usr/bin/env bash
# End-to-end checks of `shadowtune compare`: A vs A gives zero deltas and the halves of A's image,
# a worse B shows up in the deltas and the shadow diff, deltas equal B - A of `measure`, and bad
# input fails with nothing written.
# usage: compare_cli_test.sh SHADOWTUNE PRESET_DIR BAD_PRESET_DIR
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
out_has() { grep -qF -- "$1" "$work/stdout"; }
err_has() { grep -qF -- "$1" "$work/stderr"; }
jq_true() { [[ $(jq -r "$2" "$1") == true ]]; }
# same_px IMAGE_A REGION_A IMAGE_B REGION_B: the two regions (WxH+X+Y) have identical pixels
same_px() {
  oiiotool "$1" --cut "$2" -o "$work/cut1.png" && oiiotool "$3" --cut "$4" -o "$work/cut2.png" &&
    idiff -q -fail 0 -failpercent 0 "$work/cut1.png" "$work/cut2.png" >/dev/null
}
size=(--size 160x90 --frames 1)

# A: the box with 2048² hard-compare maps; B: 256² maps, known to be worse.
jq '.cascades.mapSize = 2048 | .filter.kind = "hard" | del(."$schema")' "$presets/box-over-plane.json" >"$work/box-2048.json"
jq '.cascades.mapSize = 256 | .filter.kind = "hard" | del(."$schema")' "$presets/box-over-plane.json" >"$work/box-256.json"

# A vs A (the 256² maps, so the figures are not all zero): every delta but the GPU times (timer
# noise) is exactly zero; the split halves are A's picture.
run compare "$work/box-256.json" "$work/box-256.json" --out "$work/aa" "${size[@]}"
check "A vs A exits 0" rc 0
for f in side-by-side.png split.png shadow-diff.png compare.json; do check "A vs A writes $f" test -s "$work/aa/$f"; done
j="$work/aa/compare.json"
# As many as docs/metrics.md (generated from the figure table) lists for compare, less times and flicker.
n_compared=$(grep -E '^\| `[a-zA-Z0-9.]+` \|.*\| [^|]*compare[^|]* \|' "$presets/../docs/metrics.md" |
  grep -v ' milliseconds ' | grep -vc '`flicker\.')
check "A vs A: every delta is zero (GPU ms aside)" jq_true "$j" \
  "[.delta | paths(numbers) as \$p | select((\$p | last | test(\"Ms\$\")) | not) | getpath(\$p)] | all(. == 0) and length == $n_compared"
check "A vs A: the figures compared are not all zero" jq_true "$j" '.a.accuracy.misclassified > 0'
check "A vs A: flicker delta is null without a path" jq_true "$j" '.delta.flicker.flipRate == null'
check "A vs A: no only-A / only-B pixels" jq_true "$j" '.shadowDiff.onlyA == 0 and .shadowDiff.onlyB == 0 and .shadowDiff.scoredPixels > 0'
check "A vs A: table shows zero deltas" out_has "±0 pp"
check "no temporary files left" bash -c "! ls -A '$work/aa' | grep -q tmp"
"$bin" render "$work/box-256.json" --out "$work/render" --size 160x90 >/dev/null
r="$work/render/box-256.png"
check "split: left half is A's picture" same_px "$work/aa/split.png" 79x90+0+0 "$r" 79x90+0+0
check "split: right half is A's picture" same_px "$work/aa/split.png" 79x90+81+0 "$r" 79x90+81+0
check "side-by-side: left picture is A's" same_px "$work/aa/side-by-side.png" 160x90+0+0 "$r" 160x90+0+0
check "side-by-side: right picture is A's" same_px "$work/aa/side-by-side.png" 160x90+164+0 "$r" 160x90+0+0
check "split: the label strip is below the picture" bash -c "oiiotool --info '$work/aa/split.png' | grep -qE '160 x +[0-9]+' && ! oiiotool --info '$work/aa/split.png' | grep -q '160 x   90'"

# A vs B: the 256² maps misclassify more, and the shadow tests differ somewhere.
run compare "$work/box-2048.json" "$work/box-256.json" --out "$work/ab" "${size[@]}"
check "A vs B exits 0" rc 0
j="$work/ab/compare.json"
check "A vs B: B misclassifies more" jq_true "$j" '.delta.accuracy.misclassified > 0'
check "A vs B: the shadow tests differ" jq_true "$j" '.shadowDiff.onlyA + .shadowDiff.onlyB > 0'
check "A vs B: table row with unit and sign" bash -c "grep -E '^misclassified .* \+[0-9.]+ pp$' '$work/stdout'"
check "A vs B: B's maps take less memory" jq_true "$j" '.delta.cost.shadowMapBytes < 0'
run measure "$work/box-2048.json" "$work/box-256.json" --out "$work/m" "${size[@]}" --no-flicker
check "independent measure exits 0" rc 0
ma="$work/m/box-2048/metrics.json" mb="$work/m/box-256/metrics.json"
for key in accuracy.misclassified accuracy.falseShadow accuracy.falseLight accuracy.filteredError \
           texelDensity.median texelDensity.p90 texelDensity.p95 cost.shadowMapBytes cost.casterTriangles; do
  check "delta $key = B - A of measure" bash -c "jq -n --slurpfile c '$j' --slurpfile a '$ma' --slurpfile b '$mb' \
    '(\$c[0].delta.$key - (\$b[0].$key - \$a[0].$key)) | fabs < 1e-12' | grep -q true"
done
check "delta edge band = B - A of measure" bash -c "jq -n --slurpfile c '$j' --slurpfile a '$ma' --slurpfile b '$mb' \
  'def e(m): m.accuracy.edge.falseShadow + m.accuracy.edge.falseLight;
   (\$c[0].delta.accuracy.edgeBand - (e(\$b[0]) - e(\$a[0]))) | fabs < 1e-12' | grep -q true"

# --keep-b-scene: B on its own scene; the pixels differ, so there is no shadow diff.
run compare "$work/box-2048.json" "$presets/ogldev-49.json" --out "$work/own" --keep-b-scene "${size[@]}"
check "--keep-b-scene exits 0" rc 0
check "--keep-b-scene: views are each preset's" jq_true "$work/own/compare.json" '.view.from == "each" and .shadowDiff == null'
check "--keep-b-scene: no shadow-diff.png" test ! -e "$work/own/shadow-diff.png"
check "--keep-b-scene: says why" out_has "different views"

# Bad input: a clear message, a non-zero exit, nothing written.
run compare "$work/missing.json" "$work/box-256.json" --out "$work/bad1" "${size[@]}"
check "missing preset exits non-zero" rc_nonzero
check "missing preset is named" err_has "$work/missing.json"
check "missing preset writes nothing" test ! -e "$work/bad1"
run compare "$work/box-256.json" "$data/bad-count.json" --out "$work/bad2" "${size[@]}"
check "invalid preset exits non-zero" rc_nonzero
check "invalid preset: file, JSON path, reason" err_has "bad-count.json: cascades.count: must be in 1..8, got 12"
check "invalid preset writes nothing" test ! -e "$work/bad2"
# B valid alone, but its manual split lies past A's far plane (100 m): B on A's view is invalid.
jq '.cascades.scheme = "manual" | .cascades.manualSplits = [300] | .camera.farPlane = 400 | del(."$schema")' \
  "$presets/box-over-plane.json" >"$work/far-split.json"
run compare "$work/box-256.json" "$work/far-split.json" --out "$work/bad4" "${size[@]}"
check "B invalid on A's view exits non-zero" rc_nonzero
check "B invalid on A's view: both files, JSON path, reason" \
  err_has "far-split.json on the view of $work/box-256.json: cascades.manualSplits[0]: must be in"
check "B invalid on A's view writes nothing" test ! -e "$work/bad4"
touch "$work/file" && run compare "$work/box-256.json" "$work/box-256.json" --out "$work/file/sub" "${size[@]}"
check "unusable output folder exits non-zero" rc_nonzero
check "unusable output folder is named" err_has "$work/file/sub"
run compare "$work/box-256.json" "$work/box-256.json" --out "$work/bad3" --size 10x10
check "bad size rejected" bash -c "[[ \$(cat '$work/rc') == 2 ]] && grep -qF -- '--size' '$work/stderr' && test ! -e '$work/bad3'"

echo "$failures failed"
[[ $failures == 0 ]]
