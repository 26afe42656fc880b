#!/usr/bin/env bash
# `shadowtune check` end to end on two small presets (160x90, a builtin scene): exit codes, what
# is written with and without --update, figures equal to `measure`'s, JUnit against junit.xsd
# (xmllint), one changed bias named in JUnit and first in the HTML report, opened in headless
# Chromium (--dump-dom, --screenshot), a preset named like markup shown as text, and GitHub
# annotations.
# usage: check_cli_test.sh SHADOWTUNE SOURCE_DIR [KEEP_DIR]   (KEEP_DIR: the work folder is kept there)
set -uo pipefail
bin=$1 src=$2
if [[ -n ${3:-} ]]; then work=$3; rm -rf "$work"; mkdir -p "$work"; else work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT; fi
cd "$work" || exit 1
failures=0
check() {  # check NAME CONDITION...: records a failure with NAME when the condition fails
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >stdout 2>stderr; echo $? >rc; }
rc_is() { [[ $(cat rc) == "$1" ]] && return 0; echo "  rc $(cat rc), wanted $1" >&2; sed 's/^/  stderr: /' stderr >&2; return 1; }
has() { grep -qF -- "$1" "$2" || { echo "  '$1' not in $2" >&2; return 1; }; }

injected='<img src=x onerror=alert(1)>'
mkdir -p presets
cat >presets/box.json <<'JSON'
{"version": 1, "scene": "builtin:box-over-plane",
 "camera": {"position": [0, 12, 14], "target": [0, 0, 0], "farPlane": 60},
 "cascades": {"count": 2, "mapSize": 512}, "filter": {"kind": "pcf2x2"}, "bias": {"constant": 0.02, "slope": 1.0}}
JSON
sed 's/"count": 2/"count": 1/' presets/box.json >"presets/$injected.json"
cat >suite.json <<'JSON'
{"version": 1,
 "defaults": {"size": "160x90",
              "figures": [{"figure": "misclassified", "worse_by_at_most_pp": 0.05},
                          {"figure": "softFilteredError", "worse_by_at_most_factor": 1.1},
                          {"figure": "flicker", "max": 0}]},
 "presets": ["presets/*.json"]}
JSON

# A bad suite cannot run: exit 2, with the file, the JSON path and the reason.
echo '{"version": 1, "presets": [{"preset": "presets/box.json", "figures": [{"figure": "misclassifed", "max": 1}]}]}' >bad.json
run check bad.json --golden g
check "bad suite exits 2" rc_is 2
check "bad suite names file, path, reason" has "bad.json: /presets/0/figures/0/figure: 'misclassifed' is not a figure" stderr

# No goldens: exit 1, GOLDEN_MISSING, and nothing written into the golden folder.
run check suite.json --golden g --junit out/missing.xml
check "missing golden exits 1" rc_is 1
check "missing golden is GOLDEN_MISSING" has "box: GOLDEN_MISSING" stderr
check "nothing written without --update" test ! -e g
check "missing golden in JUnit" has 'type="GOLDEN_MISSING"' out/missing.xml

# --update writes the goldens and says so; then check passes.
run check suite.json --golden g --update
check "update exits 0" rc_is 0
check "update prints what it made" has "box: NEW" stdout
for f in image.png figures.json meta.json; do check "golden has $f" test -s "g/box/$f"; done
check "meta has the renderer" bash -c "jq -e '.renderer | length > 0' g/box/meta.json >/dev/null"
check "meta has the commit and hash" bash -c "jq -e '(.commit | length > 0) and (.settingsHash | length == 16)' g/box/meta.json >/dev/null"
run check suite.json --golden g --report out/pass --junit out/pass.xml
check "check after update passes" rc_is 0
check "one progress line per preset" bash -c "[[ \$(grep -c '^\[[12]/2\] .*: PASS' stderr) == 2 ]]"
check "JUnit (pass) is valid" xmllint --noout --schema "$src/tests/check/junit.xsd" out/pass.xml
check "results.json says 0 failures" bash -c "jq -e '.failures == 0 and .exitCode == 0' out/pass/results.json >/dev/null"

# check's figures are measure's: every repeatable figure, to the last bit.
run measure presets/box.json --size 160x90 --out m --no-flicker
check "measure ran" rc_is 0
keys=$(jq -r '.results[] | select(.name == "box") | .figures[].key' out/pass/results.json)
check "figures listed" test -n "$keys"
same=1
[[ -n $keys ]] || same=0
for k in $keys; do
  path=$(jq -nc --arg k "$k" '$k | split(".")')
  a=$(jq -c "getpath($path)" g/box/figures.json) b=$(jq -c "getpath($path)" m/box/metrics.json)
  [[ $a == "$b" ]] || { echo "  $k: check $a, measure $b" >&2; same=0; }
done
check "check's figures equal measure's" test $same = 1

# One changed setting: a bias of 10 (from 0.02) detaches the box's shadow. Exit 1, the figure named in
# JUnit, the preset first in the report.
cp g/box/meta.json meta.before && cp g/box/image.png image.before
jq '.bias.constant = 10' presets/box.json >presets/tmp && mv presets/tmp presets/box.json
run check suite.json --golden g --report out/fail --junit out/fail.xml
check "a regression exits 1" rc_is 1
check "box FAILED on stderr" has "box: FAILED" stderr
check "JUnit (fail) is valid" xmllint --noout --schema "$src/tests/check/junit.xsd" out/fail.xml
check "JUnit names the figure" bash -c "xmllint --xpath 'string(//testcase[@name=\"box: accuracy.misclassified\"]/failure/@message)' out/fail.xml | grep -q '^accuracy.misclassified: misclassified .* vs golden .*pp'"
check "JUnit attaches the diff" has "[[ATTACHMENT|$work/out/fail/001-box/diff.png]]" out/fail.xml
check "no golden changed without --update" bash -c "cmp -s meta.before g/box/meta.json && cmp -s image.before g/box/image.png"
check "report images exist" test -s out/fail/001-box/diff.png

# The report in a real browser: failures first, the injected name as text, no injected element.
chrome=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $chrome ]]; then
  echo "FAIL chromium is not installed (scripts/setup.sh installs it)"; failures=$((failures + 1))
else
  flags=(--headless --no-sandbox --disable-gpu --no-first-run --disable-extensions --user-data-dir="$work/chrome")
  timeout 120 "$chrome" "${flags[@]}" --dump-dom "file://$work/out/fail/index.html" >dom.html 2>chrome.log
  check "chromium dumped the DOM" test -s dom.html
  first=$(grep -o '<span class="name">[^<]*</span>' dom.html | head -1)
  check "the failing preset is first" test "$first" = '<span class="name">box</span>'
  check "the filter box exists" has '<input id="filter"' dom.html
  check "the injected name shows as text" has '&lt;img src=x onerror=alert(1)&gt;' dom.html
  check "no injected element" bash -c "! grep -q '<img src=\"x\"' dom.html && ! grep -q 'onerror=\"' dom.html"
  check "the slider is there" has 'type="range"' dom.html
  timeout 120 "$chrome" "${flags[@]}" --dump-dom "file://$work/out/fail/index.html#filter=onerror" >filtered.html 2>>chrome.log
  check "the filter hides the others" bash -c "grep -q '<section class=\"preset failure\" data-status=\"FAILED\" hidden=\"\">' filtered.html && grep -q '<section class=\"preset\" data-status=\"PASS\">' filtered.html"
  timeout 120 "$chrome" "${flags[@]}" --hide-scrollbars --window-size=1100,1400 --screenshot="$work/report.png" \
    "file://$work/out/fail/index.html" >>chrome.log 2>&1
  check "chromium took a screenshot" test -s report.png
fi

# GitHub annotations, only when GITHUB_ACTIONS is set.
check "no annotations outside Actions" bash -c "! grep -q '^::error' stdout"
GITHUB_ACTIONS=true run check suite.json --golden g --only box
check "annotation for the failure" bash -c "grep -q '^::error file=.*presets/box.json,title=shadowtune check%3A box FAILED::' stdout"

# --update round trip: it prints the figure deltas, then check passes.
run check suite.json --golden g --update --only box
check "update of a changed preset exits 0" rc_is 0
check "update prints the delta" bash -c "grep -q '^box: UPDATED' stdout && grep -q '^  misclassified .* -> .*(+' stdout"
run check suite.json --golden g
check "after the round trip check passes" rc_is 0
run check suite.json --golden g --update
check "an unchanged golden is not rewritten" bash -c "! grep -q UPDATED stdout"

# Goldens per renderer: GOLDEN/<slug>/ is preferred, and a golden of another renderer fails.
slug=$(jq -r .renderer g/box/meta.json | tr 'A-Z' 'a-z' | sed 's/[^a-z0-9]\+/-/g; s/^-//; s/-$//')
mkdir -p "g/$slug" && cp -r g/box "g/$slug/box"
jq '.renderer = "Another GPU 1.0"' "g/$slug/box/meta.json" >t && mv t "g/$slug/box/meta.json"
run check suite.json --golden g --only box
check "another renderer's golden fails" rc_is 1
check "as RENDERER_MISMATCH" has "box: RENDERER_MISMATCH" stderr

echo "$failures failures"
exit $((failures > 0))
