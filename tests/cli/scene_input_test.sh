#!/usr/bin/env bash
# Your own glTF scene as a first-class input (app/scene_preset.h): `shadowtune init SCENE -o P`
# writes a preset that renders the scene with visible shadows on the first try, and `render SCENE`
# writes the image and the preset it made. On every scene of ../shared/assets (skipped without
# them): the ray-cast truth of the preset's view at 320x180 shows at least 0.1 % of the scene's pixels in shadow.
# Usage errors exit 2: a file that is not glTF, a preset that exists (without --force).
# Usage: scene_input_test.sh SHADOWTUNE ASSETS_DIR
set -euo pipefail
st=$1
assets=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowtune-scene-input.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
  echo "scene_input_test: FAIL: $*" >&2
  exit 1
}

set +e
"$st" init "$work/notes.txt" -o "$work/n.json" 2>"$work/err"
code=$?
set -e
[[ $code == 2 ]] && grep -q "expected a .gltf or .glb file" "$work/err" || fail "a non-glTF input: exit $code, $(cat "$work/err")"

if [[ ! -d $assets ]]; then
  echo "scene_input_test: $assets missing: the real scenes are skipped"
  exit 0
fi
mapfile -t scenes < <(find "$assets" -name '*.glb' -o -name '*.gltf' | sort)
((${#scenes[@]} >= 6)) || fail "expected the six scenes of $assets, found ${#scenes[@]}"
for scene in "${scenes[@]}"; do
  name=$(basename "${scene%.*}")
  "$st" init "$scene" -o "$work/p/$name.json" >/dev/null || fail "init $scene"
  "$st" measure "$work/p/$name.json" --size 320x180 --frames 1 --out "$work/m" >/dev/null 2>&1 || fail "measure $name"
  oiiotool "$work/m/$name/truth.png" --ch R,G,B -o "$work/truth.ppm"
  share=$(python3 - "$work/truth.ppm" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
# P6 header: magic, width, height, maxval, then RGB bytes
parts = data.split(maxsplit=4)
w, h = int(parts[1]), int(parts[2])
px = parts[4][-w * h * 3:]
shadow = lit = 0
for i in range(0, len(px), 3):
    r, g, b = px[i], px[i + 1], px[i + 2]
    if (r, g, b) == (50, 50, 50): shadow += 1
    elif (r, g, b) == (240, 240, 240): lit += 1
print(f"{shadow / max(shadow + lit, 1):.4f}")
PY
)
  echo "$name: $share of the scene's pixels in shadow"
  [[ $(echo "$share >= 0.001" | bc -l) == 1 ]] || fail "$name: only $share of its pixels in shadow"
done
"$st" render "${scenes[0]}" --out "$work/r" --size 160x90 >/dev/null || fail "render ${scenes[0]}"
name=$(basename "${scenes[0]%.*}")
[[ -s $work/r/$name.png && -s $work/r/presets/$name.json ]] || fail "render of a glTF wrote no image or preset"
set +e
"$st" init "${scenes[0]}" -o "$work/p/$name.json" 2>"$work/err"
code=$?
set -e
[[ $code == 2 ]] && grep -q "exists; --force replaces it" "$work/err" || fail "an existing preset: exit $code"
echo "scene_input_test: ok"
