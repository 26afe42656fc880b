#!/usr/bin/env bash
# `shadowtune tune` from the command line: a budget nothing meets is refused naming the cheapest
# cost; Ctrl-C keeps the evaluations made and the same command resumes to the same tuned.json as an
# uninterrupted run (the same seed gives the same result); shards on one folder reach the same result
# as one process, each measuring a share; a folder of another tune is refused; the
# tuned preset loads, and `measure` of it gives the figures the tune reported.
#   tune_cli_test.sh SHADOWTUNE SOURCE_DIR WORK_DIR
set -uo pipefail
st=$1 work=$3
rm -rf "$work" && mkdir -p "$work"
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }

cat >"$work/base.json" <<'JSON'
{"version": 1, "scene": "builtin:yard", "filter": {"kind": "pcf2x2"}, "cascades": {"count": 2, "mapSize": 512},
 "output": {"width": 96, "height": 54}}
JSON

"$st" tune "$work/base.json" --out "$work/none" --evaluations 5 >"$work/nobudget.log" 2>&1
check "no budget exits 1" "[[ $? -eq 1 ]] && grep -q 'give a budget' '$work/nobudget.log'"
"$st" tune "$work/base.json" --out "$work/tiny" --budget-ms 0.001 --evaluations 5 >"$work/tiny.log" 2>&1
check "an infeasible budget exits 1" "[[ $? -eq 1 ]]"
check "and names the cheapest cost" "grep -q 'no settings fit the budget of 0.0 ms: the cheapest (1 cascade of 256^2, hard filter) models [0-9.]* ms' '$work/tiny.log'"
check "and writes no tuned preset" "[[ ! -e '$work/tiny/tuned.json' ]]"

seed=7
# The preset's own 96x54 and 16 evaluations: enough for two shards to split a round and for a stop and a
# resume, small enough for the asan build (each evaluation renders and ray-casts every view).
args() { echo "$work/base.json --budget-ms $budget --views 2 --hold-out-every 2 --evaluations 16 --seed $seed --size 96x54"; }
run() { "$st" tune $(args) "$@"; }
budget=$("$st" measure "$work/base.json" --size 96x54 --out "$work/m0" --frames 1 --no-flicker >/dev/null 2>&1 && jq '.cost.modelMs' "$work/m0/base/metrics.json")
check "the input's modelled cost is read ($budget ms)" "[[ -n '$budget' && '$budget' != null ]]"

# The whole run also draws another preset on its front (the editor's A), which sets no budget.
cat >"$work/cmp.json" <<'JSON'
{"version": 1, "scene": "builtin:yard", "filter": {"kind": "hard"}, "cascades": {"count": 1, "mapSize": 256}}
JSON
run --out "$work/whole" --compare-with "$work/cmp.json" >"$work/whole.log" 2>&1
check "a whole tune exits 0" "[[ $? -eq 0 ]] && [[ -s '$work/whole/tuned.json' ]]"
check "it prints progress with the best so far" "grep -q 'tune \[[0-9]*/16\] best' '$work/whole.log'"
check "it explains each change" "grep -q 'alone' '$work/whole/explain.md' && jq -e '.changes | length > 0' '$work/whole/explain.json' >/dev/null"
check "it scores the held-out view" "jq -e '.tuned.heldOut.error != null and (.heldOutHolds | type == \"boolean\")' '$work/whole/summary.json' >/dev/null"
check "the front is charted" "[[ -s '$work/whole/front/pareto.png' && -s '$work/whole/front/results.csv' ]]"
# A finished tune run again with fewer evaluations (or with more, walking elsewhere once the
# polish's share moves) keeps the folder's better tuned.json: a continued tune never ends worse.
cp -r "$work/whole" "$work/fewer"
"$st" tune "$work/base.json" --budget-ms $budget --views 2 --hold-out-every 2 --evaluations 6 --seed $seed --size 96x54 \
  --out "$work/fewer" >"$work/fewer.log" 2>&1
check "a shorter run over a finished folder keeps its better tuned.json" \
  "[[ $? -eq 0 ]] && grep -q 'kept the earlier run' '$work/fewer.log' && cmp -s '$work/whole/tuned.json' '$work/fewer/tuned.json'"
p="$work/whole/progress.json" sm="$work/whole/summary.json"
check "progress.json ends done, with the summary's count and best" "jq -e --slurpfile s '$sm' '.stage == \"done\" and .evaluations == \$s[0].search.evaluations and .best.error == \$s[0].tuned.tuned.error and .best.costMs == \$s[0].tuned.tuned.costMs and .budgetMs == $budget' '$p' >/dev/null"
check "its feasible points are within the budget" "jq -e '[.points[] | select(.feasible)] | length > 0 and all(.costMs <= $budget)' '$p' >/dev/null"
check "a compared preset is drawn but sets no budget" "jq -e '.references.cmp.budget == false' '$p' >/dev/null && jq -e '.compared.cmp.tuned.costMs > 0' '$sm' >/dev/null && grep -q ',reference,cmp,' '$work/whole/front/results.csv'"

# Two shards on one folder, run at once: each measures a share, no point is measured twice, and
# the first writes the unsharded run's tuned.json and explanation (the same seed, the same search).
# A later unsharded run over the folder (the merge) makes no new evaluation and writes the same.
run --out "$work/shards" --shard 1/2 >"$work/shard1.log" 2>&1 &
s1=$!
run --out "$work/shards" --shard 2/2 >"$work/shard2.log" 2>&1
c2=$?
wait "$s1"
c1=$?
check "both shards exit 0 ($c1, $c2)" "[[ $c1 -eq 0 && $c2 -eq 0 ]]"
n1=$(wc -l <"$work/shards/evaluations.shard-1-of-2.jsonl")
n2=$(wc -l <"$work/shards/evaluations.shard-2-of-2.jsonl")
uniq=$(cat "$work/shards"/evaluations.shard-*.jsonl | jq -r '.views + " " + .id' | sort -u | wc -l)
check "each shard measures a share ($n1 + $n2)" "[[ $n1 -gt 0 && $n2 -gt 0 ]]"
check "no point is measured twice ($uniq distinct)" "[[ $uniq -eq $((n1 + n2)) ]]"
check "shard 2 leaves the outputs to shard 1" "grep -q 'shard 1 writes the results' '$work/shard2.log'"
check "the shards reach the unsharded tuned.json" "cmp -s '$work/whole/tuned.json' '$work/shards/tuned.json'"
check "and its explanation" "cmp -s '$work/whole/explain.json' '$work/shards/explain.json'"
rm "$work/shards/tuned.json"
run --out "$work/shards" >"$work/merge.log" 2>&1
check "the merge resumes from both shards' journals" "[[ $? -eq 0 ]] && grep -q 'resuming: $((n1 + n2)) evaluations' '$work/merge.log'"
check "and measures nothing new" "[[ ! -s '$work/shards/evaluations.jsonl' ]]"
check "and writes the same tuned.json" "cmp -s '$work/whole/tuned.json' '$work/shards/tuned.json'"
# A shard whose peers never run: after --shard-wait it measures their share itself.
run --out "$work/alone" --shard 1/2 --shard-wait 1 >"$work/alone.log" 2>&1
check "a shard left alone finishes the tune" "[[ $? -eq 0 ]] && grep -q 'wrote nothing in 1 s' '$work/alone.log' && cmp -s '$work/whole/tuned.json' '$work/alone/tuned.json'"
"$st" tune "$work/base.json" --budget-ms 5 --shard 3/2 --out "$work/bad" >"$work/badshard.log" 2>&1
check "a shard past the count exits 2" "[[ $? -eq 2 ]] && grep -q 'expected k/n with 1 <= k <= n' '$work/badshard.log'"

# Stopped after 6 new evaluations (as Ctrl-C stops): the evaluations are kept, and the same command
# resumes to the uninterrupted run's result.
run --out "$work/cut" --stop-after 6 >"$work/cut.log" 2>&1
made=$(wc -l <"$work/cut/evaluations.jsonl")
check "a stopped tune keeps the evaluations made ($made)" "[[ $made -eq 6 ]] && [[ ! -e '$work/cut/tuned.json' ]]"
earlier=$(jq .secondsAllRuns "$work/cut/progress.json")
run --out "$work/cut" >"$work/resume.log" 2>&1
check "the same command resumes" "[[ $? -eq 0 ]] && grep -q 'resuming: $made evaluations journaled' '$work/resume.log'"
check "its time counts the stopped run's ($earlier s) and its own" \
  "jq -e --argjson b '$earlier' '\$b > 0 and .seconds > 0 and ((.secondsAllRuns - .seconds - \$b) | if . < 0 then -. else . end) < 0.001' '$work/cut/summary.json' >/dev/null"
check "and reaches the uninterrupted run's tuned.json" "cmp -s '$work/whole/tuned.json' '$work/cut/tuned.json'"
check "the same seed gives the same explanation" "cmp -s '$work/whole/explain.json' '$work/cut/explain.json'"

# More evaluations asked of a finished tune continue its walk (its first run's screening limit is
# kept), so the result can only get better.
before=$(jq '.tuned.tuned.error' "$work/cut/summary.json")
lines=$(wc -l <"$work/cut/evaluations.jsonl")
"$st" tune "$work/base.json" --budget-ms "$budget" --views 2 --hold-out-every 2 --evaluations 24 --seed $seed --size 96x54 \
  --out "$work/cut" >"$work/more.log" 2>&1
check "more evaluations resume the finished tune" "[[ $? -eq 0 ]] && grep -q 'resuming: $lines evaluations journaled' '$work/more.log'"
check "and keep its screening limit (6 x 16)" "jq -e '.screeningLimit == 96 and .limit == 24' '$work/cut/progress.json' >/dev/null"
check "and measure new points" "[[ \$(wc -l <'$work/cut/evaluations.jsonl') -gt $lines ]]"
check "and end no worse ($before before)" "jq -e --argjson b '$before' '.tuned.tuned.error <= \$b' '$work/cut/summary.json' >/dev/null"

# Ctrl-C once the third evaluation is under way: the run stops after it, exit 130, and keeps them.
"$st" tune "$work/base.json" --budget-ms 1000 --size 320x180 --evaluations 500 --out "$work/int" >"$work/int.log" 2>&1 &
pid=$!  # not through run(): the signal must reach shadowtune
for _ in $(seq 3000); do grep -q 'tune \[3/500\]' "$work/int.log" && break; sleep 0.01; done
kill -INT "$pid"
wait "$pid"
code=$?
check "Ctrl-C exits 130 (got $code)" "[[ $code -eq 130 ]]"
check "Ctrl-C keeps the evaluations made" "[[ \$(wc -l <'$work/int/evaluations.jsonl') -ge 3 ]] && grep -q 'run the same command to resume' '$work/int.log'"

seed=8 run --out "$work/cut" >"$work/other.log" 2>&1
check "another tune's folder is refused" "[[ $? -eq 1 ]] && grep -q 'holds another tune' '$work/other.log'"

# The tuned preset's figures are measure's: the same misclassified share and modelled cost on the
# preset camera (a one-view tune).
"$st" tune "$work/base.json" --budget-ms "$budget" --views 1 --evaluations 12 --out "$work/one" >/dev/null 2>&1
"$st" measure "$work/one/tuned.json" --out "$work/m1" --frames 1 --no-flicker >/dev/null 2>&1
check "measure reads the tuned preset" "[[ -s '$work/m1/tuned/metrics.json' ]]"
same() { jq -n --argjson a "$1" --argjson b "$2" '($a - $b) | fabs <= 1e-9 * ([$a, $b] | map(fabs) | max) + 1e-12' | grep -q true; }
mis_t=$(jq '.tuned.tuned.figures["accuracy.misclassified"]' "$work/one/summary.json")
mis_m=$(jq '.accuracy.misclassified' "$work/m1/tuned/metrics.json")
cost_t=$(jq '.tuned.tuned.costMs' "$work/one/summary.json")
cost_m=$(jq '.cost.modelMs' "$work/m1/tuned/metrics.json")
check "misclassified equals measure's ($mis_t, $mis_m)" "same '$mis_t' '$mis_m'"
check "modelled cost equals measure's ($cost_t, $cost_m)" "same '$cost_t' '$cost_m'"
check "within the budget ($cost_t <= $budget)" "jq -n --argjson a '$cost_t' --argjson b '$budget' '\$a <= \$b' | grep -q true"
# A preset with a camera path: the flicker F along it is measured with every evaluation and held
# at most at the reference's (the yard's default preset has a 16-frame path; ogldev-49 has none of
# its own, so it flickers along the yard's).
"$st" tune "$2/presets/default.json" --budget-from "$2/presets/ogldev-49.json" --size 64x36 --views 1 --evaluations 8 \
  --out "$work/path" >"$work/path.log" 2>&1
check "a tune of a preset with a path exits 0" "[[ $? -eq 0 ]]"
# The reference starts the search as it is and with each analytic bias (docs/tuning.md#the-search).
ref_start() { jq -s "[.[] | select(.views == \"tuned\" and .settings.cascades.manualSplits == [25, 90] and .settings.cascades.count == 3
                     and .settings.cascades.fit == \"cascade\" and .settings.bias.$1)] | length" "$work/path/evaluations.jsonl"; }
check "the reference starts with its own bias" "[[ \$(ref_start 'constant == 0.03 and .settings.bias.slope == 1') -ge 1 ]]"
check "and with the receiver plane and half a texel of slope" "[[ \$(ref_start 'receiverPlane and .settings.bias.constant == 0 and .settings.bias.slope == 0.5 and .settings.bias.normalOffset == 0') -ge 1 ]]"
check "and with slope 1 and half a texel of normal offset" "[[ \$(ref_start 'receiverPlane == false and .settings.bias.constant == 0 and .settings.bias.slope == 1 and .settings.bias.normalOffset == 0.5') -ge 1 ]]"
f_t=$(jq '.tuned.tuned.figures["flicker.flipRate"]' "$work/path/summary.json")
f_r=$(jq '.references["ogldev-49"].tuned.figures["flicker.flipRate"]' "$work/path/summary.json")
check "every evaluation measures the path's flicker" "[[ \$(grep -c '\"views\":\"tuned\"' '$work/path/evaluations.jsonl') -eq \$(grep '\"views\":\"tuned\"' '$work/path/evaluations.jsonl' | grep -c 'flicker.flipRate\":[0-9]') ]]"
check "the tuned preset flickers no more than the reference ($f_t <= $f_r)" "jq -n --argjson a '$f_t' --argjson b '$f_r' '\$a <= \$b' | grep -q true"
exit $fail
