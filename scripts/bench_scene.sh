#!/usr/bin/env bash
# Scene benchmark of issue 11 (printed figures and ratios, never asserted): the clustered, culled,
# cached renderer against the naive one in the same run (tests/bench/scene_bench.cpp).
# usage: scripts/bench_scene.sh [BUILD_DIR]   (defaults to build/release; needs ../shared/assets
#   for Truck Town, xvfb-run for the editor; SCALE="10000 100000" to shorten the scale series,
#   CAMERAS=low to view it from one corner only)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
bench=$build/tests/bench/scene_bench
[[ -x $bench ]] || { echo "error: $bench not built (cmake --build $build --target scene_bench)" >&2; exit 1; }
out=$(mktemp -d) && trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(glxinfo -B 2>/dev/null | grep -m1 'renderer string' | cut -d: -f2 | xargs || echo 'Mesa (EGL)')"

town=$root/presets/scenes/truck-town.json
echo
echo "== Truck Town, 1280x720, 4 x 2048 maps"
if [[ -d $root/../shared/assets/truck_town ]]; then
  nice "$bench" "$town" --size 1280x720 --map 2048 --frames 7
else
  echo "skipped: ../shared/assets/truck_town not found"
fi

echo
echo "== Editor under Xvfb (median frame of a scripted run)"
if command -v xvfb-run >/dev/null && [[ -x $build/shadowtune ]] && [[ -d $root/../shared/assets/truck_town ]]; then
  echo -n "  still camera, truck-town: "
  (cd "$out" && nice xvfb-run -a -s "-screen 0 1280x800x24" "$build/shadowtune" editor "$town" --frames 30 2>&1 | grep "median frame" || echo "no figure")
  echo "  moving camera: not measured (the editor has no scripted camera path; scene_bench's 'moving' row is the same renderer)"
else
  echo "skipped: needs xvfb-run, the shadowtune binary and Truck Town"
fi

echo
echo "== Scale series: boxes over a 400 m field, 1280x720, 4 x 2048 maps (generated into $out)"
echo "   camera at the field's low corner (-x,-z) and its high corner (+x,+z): the clusters' build order is"
echo "   front to back from the first, back to front from the second; 'passed depth' is the fragments shaded"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for tris in ${SCALE:-10000 100000 1200000}; do
  for layout in one-mesh nodes; do
    for camera in ${CAMERAS:-low high}; do
      preset=$(python3 "$root/scripts/gen_box_field.py" "$out" "$tris" "$layout" --camera "$camera")
      echo "  -- $layout, camera $camera"
      nice "$bench" "$preset" --frames 3 | sed 's/^/  /'
    done
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

if [[ -x $root/scripts/bench_depth_bounds.sh ]]; then
  echo
  echo "== Depth bounds (scripts/bench_depth_bounds.sh)"
  "$root/scripts/bench_depth_bounds.sh" "$build"
fi
