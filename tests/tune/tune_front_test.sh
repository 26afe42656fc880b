#!/usr/bin/env bash
# `shadowtune tune --front` against a grid of the same evaluation count, on the yard at a small
# size (scripts/front_vs_grid.sh): the grid sweeps the shipped sweeps' axes (count, map size, fit,
# split weight; 54 points) and the tune makes 54 evaluations. With --front every point of the
# grid's front is matched by a tune point at no more modelled cost and no more soft filtered
# error; without it (the same search, no descent) the cheap end of the grid's front is not.
# The front's summary and chart say what a user needs to read them.
#   tune_front_test.sh SHADOWTUNE SOURCE_DIR WORK_DIR
set -uo pipefail
st=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }

# 192x108: at 96x54 the grid's one 512^2 map and the tune's cheapest points differ by hundredths
# of a millisecond and a few pixels, which says little of either.
cat >"$work/base.json" <<'JSON'
{"version": 1, "scene": "builtin:yard", "filter": {"kind": "pcf2x2"}, "cascades": {"count": 2, "mapSize": 512},
 "output": {"width": 192, "height": 108}}
JSON
cat >"$work/grid.json" <<'JSON'
{"version": 1, "base": "base.json",
 "axes": [
    {"field": "cascades.count", "values": [1, 2, 4]},
    {"field": "cascades.mapSize", "values": [512, 1024, 2048]},
    {"field": "cascades.fit", "values": ["cascade", "sphere"]},
    {"field": "cascades.lambda", "values": [0.5, 0.8, 0.95]}
 ]}
JSON

ST=$st "$src/scripts/front_vs_grid.sh" "$work/grid.json" "$work/base.json" "$work/front" 54 >"$work/front.log" 2>&1
code=$?
cat "$work/front.log"
check "the tune's front dominates the grid's with the grid's 54 evaluations (exit $code)" "[[ $code -eq 0 ]]"
check "it says so" "grep -q 'dominated: \([0-9]*\) of \1 grid front points, with 54 evaluations' '$work/front.log'"
s="$work/front/tune/summary.json"
check "the descent made rungs" "jq -e '.search.frontRungs > 0' '$s' >/dev/null"
check "summary.json lists the front, cheapest first, each point within the budget" \
  "jq -e '. as \$s | (.front | length) > 2 and ([.front[].costMs] == ([.front[].costMs] | sort)) and all(.front[]; .costMs <= \$s.budgetMs)' '$s' >/dev/null"
check "no front point is beaten in both cost and error by another" \
  "jq -e '[.front[] as \$a | .front[] as \$b | select(\$b.costMs < \$a.costMs and \$b.error < \$a.error)] | length == 0' '$s' >/dev/null"
check "the tune prints its front" "grep -q '^front: [0-9]* points within the budget, from' '$work/front/tune.log'"
check "the front is charted" "[[ -s '$work/front/tune/front/pareto.png' ]]"
check "the tuned preset loads" "'$st' measure '$work/front/tune/tuned.json' --out '$work/m' --frames 1 --no-flicker >/dev/null 2>&1"

NO_FRONT=1 ST=$st "$src/scripts/front_vs_grid.sh" "$work/grid.json" "$work/base.json" "$work/walk" 54 >"$work/walk.log" 2>&1
code=$?
check "without --front the same search leaves grid front points unmatched (exit $code)" "[[ $code -eq 3 ]] && grep -q '| none |' '$work/walk/table.md'"

# The descent's own option checks.
"$st" tune "$work/base.json" --out "$work/bad" --budget-ms 5 --constraints some >"$work/bad.log" 2>&1
check "--constraints takes artifacts or none" "[[ $? -ne 0 ]] && grep -q 'constraints' '$work/bad.log'"
"$st" tune "$work/base.json" --out "$work/front/tune" --budget-ms 5 --evaluations 4 >"$work/other.log" 2>&1
check "a folder of a --front tune is not resumed by another tune" "[[ $? -ne 0 ]] && grep -q 'holds another tune' '$work/other.log'"
exit $fail
