#!/usr/bin/env bash
# The main job: set up (if needed), build, then open the editor when a display exists, otherwise
# replay every preset headless into out/. Extra arguments go to shadowtune.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
if [[ -n "${DISPLAY:-}" ]] && build/release/shadowtune --help 2>/dev/null | grep -q '^  editor'; then
  exec build/release/shadowtune editor "$@"
fi
[[ -n "${DISPLAY:-}" ]] || echo "run: no DISPLAY, replaying presets headless into out/"
exec build/release/shadowtune render presets/*.json --out out "$@"
