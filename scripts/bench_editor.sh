#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): the editor's frame rate on Truck Town at 1280x720
# with 4x2048 maps under Xvfb, the camera still and moving (`--orbit`: a turn of 1 degree per
# frame around the target, as a drag would), with the panels docked (the scene in the viewport
# they leave) and hidden (the scene fills the window), in the same run: medians of the UI frame,
# of the scene renders (with the interactive scale they ran at) and how many frames reused the
# image; and how long closing the window takes. Needs xvfb-run and ../shared/assets.
#   scripts/bench_editor.sh [BUILD_DIR] [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
frames=${2:-60}
st=$(realpath "$build/shadowtune")
cfg=$(mktemp -d)
trap 'rm -rf "$cfg"' EXIT
mkdir -p "$cfg/shadowtune"
echo '{"width": 1280, "height": 720}' >"$cfg/shadowtune/window.json"
run() {  # $1: panelsHidden, $2: degrees per frame; prints the editor's frame-time lines and close time
    echo "{\"panelsHidden\": $1}" >"$cfg/shadowtune/layout.json"
    XDG_CONFIG_HOME="$cfg" xvfb-run -a -s '-screen 0 1920x1200x24' "$st" editor presets/scenes/truck-town.json \
        --frames "$frames" --orbit "$2" --layout-report "$cfg/layout-report.json" 2>&1 |
        grep -E "median frame|scene rendered|closed in" | tr '\n' ' '
    echo "(scene $(python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['scene']; print('%dx%d' % (s[2], s[3]))" "$cfg/layout-report.json"))"
}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "truck-town 1280x720 window, 4x2048 maps, $frames frames:"
echo "  still,  panels docked: $(run false 0)"
echo "  still,  panels hidden: $(run true 0)"
echo "  moving, panels docked: $(run false 1)"
echo "  moving, panels hidden: $(run true 1)"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
