#!/usr/bin/env bash
# `render` and `measure` warn on stderr about cut casters and wasted maps, with the likely fix,
# and stay quiet on a preset that has neither.
# usage: warnings_cli_test.sh SHADOWTUNE PRESET_DIR DATA_DIR
set -uo pipefail
bin=$1 presets=$2 data=$3
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
check() {
  local name=$1; shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; failures=$((failures + 1)); fi
}
run() { "$bin" "$@" >"$work/stdout" 2>"$work/stderr"; echo $? >"$work/rc"; }
rc() { [[ $(cat "$work/rc") == "$1" ]]; }
err_has() { grep -qE -- "$1" "$work/stderr"; }
no_warning() { ! grep -q "warning:" "$work/stderr"; }

for cmd in render measure; do
  extra=()
  [[ $cmd == measure ]] && extra=(--frames 1 --no-flicker)
  run $cmd "$data/warn-z-extension.json" --out "$work/$cmd-z" "${extra[@]}"
  check "$cmd: z-extension preset exits 0" rc 0
  check "$cmd: z-extension warning names cascade, setting and minimum" \
    err_has "warn-z-extension.json: warning: cascade [0-9]: z-extension 1 m cuts casters up to [0-9.]+ m toward the sun; minimal extension [0-9.]+ m"

  run $cmd "$data/warn-wasted.json" --out "$work/$cmd-w" "${extra[@]}"
  check "$cmd: wasted preset exits 0" rc 0
  check "$cmd: wasted map warning with the fix" \
    err_has "warn-wasted.json: warning: cascade 0: median [0-9.]+ screen pixels per shadow texel \(limit 4\); likely fix: cascades.depthBounds \"fit\" or cascades.shadowDistance"
  run $cmd "$data/warn-wasted.json" --out "$work/$cmd-w2" --warn-pixels-per-texel 100000 --warn-texel 1000 "${extra[@]}"
  check "$cmd: stated limits above the figures silence it" no_warning

  run $cmd "$presets/box-over-plane.json" --out "$work/$cmd-q" --size 160x90 "${extra[@]}"
  check "$cmd: quiet preset exits 0" rc 0
  check "$cmd: quiet preset warns nothing" no_warning
done
check "render: warnings in the statistics" grep -q '"cascade 0: median' "$work/render-w/warn-wasted.json"
check "measure: warnings and depth bounds in metrics.json" \
  bash -c "grep -q '\"warnings\"' '$work/measure-w/warn-wasted/metrics.json' && grep -q '\"depthBounds\"' '$work/measure-w/warn-wasted/metrics.json'"
run render "$data/warn-wasted.json" --out "$work/bad" --warn-texel -1
check "a bad limit exits non-zero" bash -c "[[ \$(cat '$work/rc') != 0 ]]"
exit $((failures > 0))
