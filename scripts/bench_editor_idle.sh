#!/usr/bin/env bash
# Benchmark (prints figures, asserts nothing): what the editor costs while nobody touches it
# (issue 21 #2). Truck Town under Xvfb, the window WxH (default 1000x700); once the editor has
# settled (its --status-file says idle, or after WARMUP seconds for a build without that option),
# the CPU ticks of the whole process (every thread: the UI, llvmpipe's, the Accuracy job's) are
# read from /proc/PID/stat over 10 s, and printed as a share of one core, with the frames drawn
# meanwhile when the build reports them. The machine and its load are printed before and after.
#   scripts/bench_editor_idle.sh [SHADOWTUNE_BINARY] [WxH] [WARMUP]
# The "before" figure of issue 21: scripts/bench_editor_idle.sh /work/main/build/release/shadowtune
set -euo pipefail
cd "$(dirname "$0")/.."
st=$(realpath "${1:-build/release/shadowtune}")
size=${2:-1000x700}
warmup=${3:-45}
seconds=10
cfg=$(mktemp -d)
pid=
cleanup() {
    [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null && kill -INT "$pid" 2>/dev/null
    sleep 1
    [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null
    rm -rf "$cfg"
}
trap cleanup EXIT
mkdir -p "$cfg/shadowtune"
echo "{\"width\": ${size%x*}, \"height\": ${size#*x}}" >"$cfg/shadowtune/window.json"
status_opt=()
if "$st" editor --help 2>/dev/null | grep -q -- --status-file; then status_opt=(--status-file "$cfg/status.json"); fi
cat >"$cfg/run.sh" <<SCRIPT
"$st" editor presets/scenes/truck-town.json ${status_opt[*]:-} >"$cfg/editor.txt" 2>&1 &
echo \$! >"$cfg/pid"
wait
SCRIPT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
XDG_CONFIG_HOME="$cfg" xvfb-run -a -s '-screen 0 1920x1200x24' bash "$cfg/run.sh" >/dev/null 2>&1 &
for _ in $(seq 600); do [ -s "$cfg/pid" ] && break; sleep 0.1; done
pid=$(cat "$cfg/pid")
frames() { sed -n 's/.*"frames": *\([0-9]*\).*/\1/p' "$cfg/status.json" 2>/dev/null; }
if [ ${#status_opt[@]} -gt 0 ]; then
    start=$SECONDS
    until grep -q '"idle": *true' "$cfg/status.json" 2>/dev/null; do
        kill -0 "$pid" 2>/dev/null || { echo "the editor ended: $(cat "$cfg/editor.txt")"; exit 1; }
        [ $((SECONDS - start)) -gt 600 ] && { echo "the editor did not settle in 600 s"; exit 1; }
        sleep 0.2
    done
    echo "settled (status idle) after $((SECONDS - start)) s; $(sed -n 's/.*"accuracy": *"\([^"]*\)".*/\1/p' "$cfg/status.json" | cut -c1-90)"
else
    sleep "$warmup"
    echo "no --status-file in this build: measured after a fixed warm-up of $warmup s"
fi
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
hz=$(getconf CLK_TCK)
f0=$(frames || true)
t0=$(ticks)
sleep "$seconds"
t1=$(ticks)
f1=$(frames || true)
used=$((t1 - t0))
share=$(awk -v u="$used" -v hz="$hz" -v s="$seconds" 'BEGIN { printf "%.1f", 100 * u / (hz * s) }')
echo "truck-town ${size}, idle ${seconds} s: ${used} ticks of ${hz}/s = ${share} % of a core${f0:+, frames drawn $((f1 - f0))}"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
