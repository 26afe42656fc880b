#!/usr/bin/env bash
# `shadowtune sweep` from the command line: a bad sweep file is refused with the path and reason
# and writes nothing; Ctrl-C stops after the current point with its results kept, and the same
# command resumes; a folder of another sweep is refused; shards merge.
#   sweep_cli_test.sh SHADOWTUNE SOURCE_DIR WORK_DIR
set -uo pipefail
st=$1 work=$3
rm -rf "$work" && mkdir -p "$work"
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }

cat >"$work/base.json" <<'JSON'
{"version": 1, "scene": "builtin:box-over-plane", "filter": {"kind": "hard"},
 "camera": {"position": [0, 8, 10], "target": [0, 0, 0], "farPlane": 60}, "output": {"width": 48, "height": 32}}
JSON
cat >"$work/s.json" <<'JSON'
{"version": 1, "base": "base.json", "axes": [{"field": "cascades.count", "values": [1, 2, 3]},
 {"field": "cascades.mapSize", "values": [256, 512]}]}
JSON
# Slow enough that Ctrl-C lands mid-sweep: bigger frames and maps, more points.
cat >"$work/slow.json" <<'JSON'
{"version": 1, "base": "base.json", "set": {"output.width": 320, "output.height": 180},
 "axes": [{"field": "cascades.count", "values": [1, 2, 3, 4]}, {"field": "cascades.mapSize", "values": [1024, 2048, 4096]}]}
JSON
cat >"$work/other.json" <<'JSON'
{"version": 1, "base": "base.json", "axes": [{"field": "cascades.count", "values": [1, 2]}]}
JSON
cat >"$work/bad.json" <<'JSON'
{"version": 1, "base": "base.json", "axes": [{"field": "cascades.mapSize", "values": [256, 300]}]}
JSON

"$st" sweep "$work/bad.json" --out "$work/bad-out" >"$work/bad.log" 2>&1
check "bad sweep exits 1" "[[ $? -eq 1 ]]"
check "bad sweep names file, path and reason" "grep -q 'bad.json: axes\[0\].values\[1\]: must be a power of two' '$work/bad.log'"
check "bad sweep writes nothing" "[[ ! -e '$work/bad-out' ]]"

# Ctrl-C once the first point is reported: the run stops after the point it is on.
"$st" sweep "$work/slow.json" --out "$work/run" --frames 3 >"$work/int.log" 2>&1 &
pid=$!
for _ in $(seq 3000); do grep -q "sweep: 1/12" "$work/int.log" && break; sleep 0.02; done
kill -INT "$pid"
wait "$pid"
code=$?
done_points=$(ls "$work/run/points" 2>/dev/null | wc -l)
check "Ctrl-C exits 130 (got $code)" "[[ $code -eq 130 ]]"
check "Ctrl-C keeps the points done ($done_points of 12)" "[[ $done_points -ge 1 && $done_points -lt 12 ]]"
check "Ctrl-C still writes the report" "[[ -s '$work/run/results.csv' && -s '$work/run/pareto.png' ]]"
"$st" sweep "$work/slow.json" --out "$work/run" --frames 1 >"$work/resume.log" 2>&1
check "resume exits 0" "[[ $? -eq 0 ]]"
check "resume finds the points done" "grep -q '$done_points resumed' '$work/resume.log'"
check "resumed run has every point" "[[ \$(ls '$work/run/points' | wc -l) -eq 12 && \$(wc -l <'$work/run/results.csv') -eq 13 ]]"

"$st" sweep "$work/other.json" --out "$work/run" >"$work/other.log" 2>&1
check "another sweep's folder is refused" "[[ $? -eq 2 ]] && grep -q 'holds results of another sweep' '$work/other.log'"

# A folder written before the figure table's keys (results version 1): refused, saying what to do.
mkdir -p "$work/old" && jq '.version = 1' "$work/run/sweep.json" >"$work/old/sweep.json"
"$st" sweep "$work/slow.json" --out "$work/old" >"$work/old.log" 2>&1
check "an old results folder is refused" "[[ $? -eq 2 ]] && grep -q 'sweep.json: written with sweep results version 1' '$work/old.log' && grep -q 'another --out' '$work/old.log'"
check "results.csv columns are the figure table's keys" "head -1 '$work/run/results.csv' | grep -q ',accuracy.misclassified,.*,cost.gpuMs,'"
"$st" sweep "$work/s.json" --out "$work/q" --cost misclassified >"$work/cost.log" 2>&1
check "a --cost that is no cost is refused" "[[ $? -ne 0 ]] && grep -q 'measured' '$work/cost.log'"

"$st" sweep "$work/s.json" --out "$work/shard1" --shard 1/2 --frames 1 >/dev/null 2>&1 &&
  "$st" sweep "$work/s.json" --out "$work/shard2" --shard 2/2 --frames 1 >/dev/null 2>&1 &&
  "$st" sweep --merge "$work/shard1" "$work/shard2" --out "$work/merged" >"$work/merge.log" 2>&1
check "shards merge into every point" "grep -q 'merged 2 shard folders: 6 points' '$work/merge.log'"
"$st" sweep "$work/s.json" --out "$work/x" --shard 3/2 >"$work/shard.log" 2>&1
check "a bad --shard is refused" "[[ $? -eq 1 ]] && grep -q 'expected k/n' '$work/shard.log'"
exit $fail
