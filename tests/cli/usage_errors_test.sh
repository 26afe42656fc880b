#!/usr/bin/env bash
# Hostile values on the command line (issue "The artist's third pass"): every numeric option refuses
# NaN, infinity and out-of-range numbers with one line naming the option, the value and the allowed
# range in plain numbers, exits 2, and writes nothing (the output folder is not even created).
# Usage: usage_errors_test.sh SHADOWTUNE PRESETS_DIR
set -euo pipefail
st=$1
presets=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowtune-usage.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0

# expect OUTDIR PATTERN -- ARGS...: shadowtune ARGS exits 2, prints one line matching PATTERN, and
# leaves no OUTDIR.
expect() {
  local out=$1 pattern=$2
  shift 3
  local code=0
  "$st" "$@" >"$work/stdout" 2>"$work/stderr" || code=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [[ $code != 2 ]] || ! grep -qE -- "$pattern" "$work/stderr" || [[ $lines != 1 ]] || [[ -e $out ]]; then
    echo "FAIL shadowtune $*: exit $code, $lines lines, $( [[ -e $out ]] && echo "$out written" ): $(cat "$work/stderr")"
    failures=$((failures + 1))
  else
    echo "ok   shadowtune $*: $(cat "$work/stderr")"
  fi
}

p=$presets/default.json
expect "$work/t1" "--budget-ms: 'nan' is not a finite number" -- tune "$p" --budget-ms nan --out "$work/t1"
expect "$work/t2" "--budget-ms: 0 is outside \(0, inf\)" -- tune "$p" --budget-ms 0 --out "$work/t2"
expect "$work/t3" "--budget-mib: 'inf' is not a finite number" -- tune "$p" --budget-mib inf --out "$work/t3"
expect "$work/t4" "--shard-wait: -1 is outside" -- tune "$p" --shard-wait -1 --out "$work/t4"
expect "$work/s1" "--stop-after: 'nan' is not a number|--stop-after: 'nan' is not a finite number" -- sweep "$presets/sweeps/fox.json" --stop-after nan --out "$work/s1"
expect "$work/r1" "--warn-texel: 'nan' is not a finite number" -- render "$p" --warn-texel nan --out "$work/r1"
expect "$work/m1" "--frames: 0 is outside 1 .. 1000" -- measure "$p" --frames 0 --out "$work/m1"
expect "$work/e1" "--orbit: 91 is outside -45 .. 45" -- editor "$p" --orbit 91 --frames 1
if ((failures)); then
  echo "usage_errors_test: $failures failed"
  exit 1
fi
