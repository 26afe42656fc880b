#!/usr/bin/env bash
# A tune's front against a sweep grid's front (docs/tuning.md#front): sweeps the grid, then tunes
# the preset with --front at the grid front's highest modelled cost, on the preset camera alone
# (the grid's one view), with the objective alone (the grid knows no constraints), and prints
# each grid front point with the tune point that is at least as cheap and as good, if any.
# Exits 0 when the tune's front dominates the grid's, 3 when it does not.
#   scripts/front_vs_grid.sh SWEEP PRESET OUT [EVALUATIONS] [more tune options...]
# EVALUATIONS defaults to a quarter of the grid's points. ST names the binary (default
# build/release/shadowtune); NO_FRONT=1 tunes without --front, to compare.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
st=${ST:-$root/build/release/shadowtune}
[[ $# -ge 3 ]] || { echo "usage: $0 SWEEP PRESET OUT [EVALUATIONS] [tune options...]" >&2; exit 2; }
sweep=$1 preset=$2 out=$3
shift 3
mkdir -p "$out"
"$st" sweep "$sweep" --out "$out/grid" --error soft-filtered --cost model --frames 1 >"$out/grid.log" 2>&1 ||
  { echo "error: the sweep failed, see $out/grid.log" >&2; exit 1; }
points=$(jq '[.points[] | select(.reference | not)] | length' "$out/grid/results.json")
evaluations=${1:-$((points / 4))}
[[ $# -gt 0 ]] && shift
# The budget: the costliest point of the grid's own front (the lowest error; the cheapest of equals).
top=$(jq '[.points[] | select(.reference | not) | {c: .figures."cost.modelMs", e: .figures."soft.filteredError"}
           | select(.c != null and .e != null)] | min_by([.e, .c]).c' "$out/grid/results.json")
front=(--front)
[[ ${NO_FRONT:-0} == 1 ]] && front=()
"$st" tune "$preset" --out "$out/tune" --budget-ms "$top" --evaluations "$evaluations" --views 1 --hold-out-every 0 \
  --constraints none "${front[@]}" "$@" >"$out/tune.log" 2>&1 ||
  { echo "error: the tune failed, see $out/tune.log" >&2; exit 1; }
made=$(jq '.search.evaluations' "$out/tune/summary.json")
echo "grid: $points points ($out/grid); tune: $made evaluations ($out/tune), budget $top ms"
echo "| grid front point | modelled cost | soft filtered | tune point at most as costly and as wrong | modelled cost | soft filtered |"
echo "|---|---|---|---|---|---|"
jq -r --slurpfile tune "$out/tune/front/results.json" '
  def ms: (. * 100 | round) / 100 | tostring + " ms";
  def num: (. * 100000 | round) / 100000 | tostring;
  # A results.json'"'"'s own points (not the references) as {label, c: modelled cost, e: error}.
  def own: [.points[] | select(.reference | not) | {label: .label, c: .figures."cost.modelMs", e: .figures."soft.filteredError"}
            | select(.c != null and .e != null)];
  # Not "tuned": after the search the tuned point is simplified (docs/tuning.md), measurements past
  # the evaluations counted here; unsimplified it is also there as its own evaluation.
  ($tune[0] | own | map(select(.label != "tuned"))) as $t
  | own | . as $all
  | [.[] | . as $p | select([$all[] | select(.c <= $p.c and .e <= $p.e and (.c < $p.c or .e < $p.e))] | length == 0)]
  | unique_by([.c, .e]) | sort_by(.c)[]
  | . as $g
  | ([$t[] | select(.c <= $g.c and .e <= $g.e)] | min_by(.e)) as $d
  | "| \($g.label) | \($g.c | ms) | \($g.e | num) | "
    + (if $d then "\($d.label) | \($d.c | ms) | \($d.e | num) |" else "none | | |" end)' \
  "$out/grid/results.json" >"$out/table.md" || { echo "error: cannot read the results" >&2; exit 1; }
cat "$out/table.md"
total=$(grep -c '^| ' "$out/table.md" || true)
missed=$(grep -c '| none |' "$out/table.md" || true)
echo "dominated: $((total - missed)) of $total grid front points, with $made evaluations against the grid's $points"
[[ $missed -eq 0 ]] || exit 3
