#!/usr/bin/env bash
# Checks that the factor the three.js page captures is the factor three.js applies: renders the
# driver test's scene as the capture, as three.js's own colour, and as its colour with shadow receiving
# off, and requires colour / unshadowed == factor on every sunlit pixel (test/crosscheck.mjs), for
# PCF, PCF with fade, VSM with fade and Basic with 4 cascades. 12 Chromium runs (~30-40 s).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowtune-hook-crosscheck.XXXXXX")
trap 'rm -rf "$work"' EXIT
job=$(node "$here/make_scene.mjs" "$work" threejs)
node "$here/crosscheck.mjs" "$job" '{}' '{"fade":true}' '{"shadowMapType":"VSMShadowMap","fade":true}' \
  '{"shadowMapType":"BasicShadowMap","cascades":4,"radius":3}'
