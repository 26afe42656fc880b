#!/usr/bin/env bash
# Every engine preset loads and renders: `shadowtune render presets/engines/*.json` exits 0.
# usage: render_engine_presets.sh SHADOWTUNE ENGINE_PRESET_DIR
set -uo pipefail
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
"$1" render "$2"/*.json --out "$work" --size 160x90 || exit 1
for p in "$2"/*.json; do
  test -s "$work/$(basename "${p%.json}").png" || { echo "FAIL no image for $p"; exit 1; }
done
echo "all engine presets rendered"
