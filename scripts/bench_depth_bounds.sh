#!/usr/bin/env bash
# Benchmark of depth-fitted cascades (sample distribution shadow maps, issue 11 item 1): Truck Town
# at 1280x720 with 4 x 2048 maps, measured with cascades.depthBounds "off" (the preset as it is),
# "fit", "fit" with fit "samples", and that with the logarithmic scheme (SDSM's partition), all in
# one run. Prints the screen pixels per shadow texel
# (median, p95), the misclassified share against the ray-cast truth, the split range and the GPU
# times, and each figure of the fitted runs as a ratio of the preset's.
# Targets (issue 11): median <= 4 and misclassification at most half of the preset's.
# usage: scripts/bench_depth_bounds.sh [BUILD_DIR] [PRESET]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
preset=${2:-$root/presets/scenes/truck-town.json}
if [[ ! -d $root/../shared/assets/truck_town && $# -lt 2 ]]; then
  echo "error: ../shared/assets/truck_town not found (give a PRESET)" >&2
  exit 1
fi
out=$(mktemp -d) && trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
# The variants: the preset with its scene path made absolute, 4 cascades of 2048.
python3 - "$preset" "$out" <<'PY'
import json, os, sys
src, out = sys.argv[1], sys.argv[2]
p = json.load(open(src))
if not p["scene"].startswith("builtin:"):
    p["scene"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(src)), p["scene"]))
p.pop("$schema", None)
p["cascades"].update({"count": 4, "mapSize": 2048})
for name, extra in [("off", {"depthBounds": "off"}), ("fit", {"depthBounds": "fit"}),
                    ("fit-samples", {"depthBounds": "fit", "fit": "samples"}),
                    ("fit-samples-log", {"depthBounds": "fit", "fit": "samples", "scheme": "logarithmic"})]:
    q = json.loads(json.dumps(p))
    q["cascades"].update(extra)
    json.dump(q, open(os.path.join(out, name + ".json"), "w"), indent=1)
PY
"$build/shadowtune" measure "$out/off.json" "$out/fit.json" "$out/fit-samples.json" "$out/fit-samples-log.json" --out "$out/m" \
  --size 1280x720 --frames 5 --no-flicker >"$out/log" 2>"$out/err" || { cat "$out/log" "$out/err"; exit 1; }
grep -v "^ " "$out/log" | sed "s|$out/m/||" || true
python3 - "$out/m" <<'PY'
import json, os, sys
d = sys.argv[1]
variants = ["off", "fit", "fit-samples", "fit-samples-log"]
rows = {n: json.load(open(os.path.join(d, n, "metrics.json"))) for n in variants}
base = rows["off"]
def fig(m):
    f = m["frame"]; c = m["cost"]
    return {"median": m["texelDensity"]["median"], "p95": m["texelDensity"]["p95"],
            "miscl": m["accuracy"]["misclassified"], "shadow": c["gpuShadowMs"], "main": c["gpuMainMs"],
            "range": f["splitRange"], "seen": (f["depthBounds"]["seenNear"], f["depthBounds"]["seenFar"]),
            "bounds": f["gpuDepthBoundsMs"]}
b = fig(base)
print(f"{'variant':<16} {'px/texel median':>16} {'p95':>8} {'misclassified':>14} {'split range (m)':>20} "
      f"{'GPU shadow ms':>14} {'main ms':>8} {'bounds ms':>10}")
for n, m in rows.items():
    f = fig(m)
    rng = f"{f['range'][0]:.2f}..{f['range'][1]:.1f}"
    print(f"{n:<16} {f['median']:>16.2f} {f['p95']:>8.1f} {100*f['miscl']:>13.3f}% {rng:>20} "
          f"{f['shadow']:>14.1f} {f['main']:>8.1f} {f['bounds']:>10.1f}")
for n in variants[1:]:
    f = fig(rows[n])
    ok_med = f["median"] <= 4.0
    ok_mis = f["miscl"] <= 0.5 * b["miscl"]
    print(f"{n}: median {f['median']:.2f} ({f['median']/b['median']:.2f}x off; target <= 4: {'met' if ok_med else 'NOT met'}), "
          f"misclassified {f['miscl']/b['miscl']:.2f}x off (target <= 0.5x: {'met' if ok_mis else 'NOT met'}), "
          f"GPU shadow {f['shadow']/b['shadow']:.2f}x, seen depths {f['seen'][0]:.2f}..{f['seen'][1]:.1f} m")
PY
