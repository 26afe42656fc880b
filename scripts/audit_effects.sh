#!/usr/bin/env bash
# audit_effects.sh: measures, on truck-town's preset view, the effect of the approximations left in
# the audited engines' presets (docs/engines.md, "The audited engines") that a shadowtune setting
# can switch. For each engine it builds <engine>-base.json: presets/scenes/truck-town.json with the
# engine preset's "cascades", "filter" and "bias" objects put over it (scene path made absolute),
# then variants with one setting switched, and runs `shadowtune measure BASE VARIANT...` for each
# pair (one at a time) with --no-flicker --frames 1. It ends with a table of
# accuracy.misclassified, soft.filteredError and cost.modelMs per preset.
#
# Run from anywhere (no build needed):
#   scripts/audit_effects.sh
# Environment: SHADOWTUNE (the binary, default /tmp/st-bin14/shadowtune), AUDIT_DIR (output, default
# /tmp/audit). Output: AUDIT_DIR/<pair>/<preset>/metrics.json, AUDIT_DIR/<pair>.log, and the
# summary on stdout (also in AUDIT_DIR/summary.tsv).
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=${SHADOWTUNE:-/tmp/st-bin14/shadowtune}
OUT=${AUDIT_DIR:-/tmp/audit}
mkdir -p "$OUT"
cd "$ROOT"  # measure finds ../shared/assets from the repository root

SCENE=$(cd presets/scenes && realpath "$(jq -r .scene truck-town.json)")

base() {  # engine
    jq -s --arg s "$SCENE" '.[0] + {cascades: .[1].cascades, filter: .[1].filter, bias: .[1].bias} | .scene = $s' \
        presets/scenes/truck-town.json "presets/engines/$1.json" >"$OUT/$1-base.json"
}
variant() {  # engine name jq-filter (applied to the engine's base)
    jq "$3" "$OUT/$1-base.json" >"$OUT/$1-$2.json"
}
pair() {  # out-name preset-names...
    local name=$1
    shift
    local files=()
    for p in "$@"; do files+=("$OUT/$p.json"); done
    echo "measuring $name: $*" >&2
    "$BIN" measure "${files[@]}" --out "$OUT/$name" --no-flicker --frames 1 >"$OUT/$name.log" 2>&1
}

for e in godot unity unreal bevy filament; do base "$e"; done

# Godot: a 3-cascade preset (splits 10.09, 20.08; fade from 80 m) against its export to Godot's 4
# splits (the third halfway through the last cascade, 60.04 m; the same fade start).
variant godot 3c '.cascades.count = 3 | .cascades.manualSplits = [10.09, 20.08] | .cascades.fadeBand = 0.25025'
variant godot 3c-as4 '.cascades.manualSplits = [10.09, 20.08, 60.04] | .cascades.fadeBand = 0.5005'
# Godot: every caster kept (scene-bounds), as the pancake clamp keeps them, against the 20 m reach.
variant godot scenebounds '.cascades.zExtension = "scene-bounds" | del(.cascades.zExtensionDistance)'
# Godot: the depth bias per split, (2 r_i + 20) / (2 r_0 + 20) of the corners'-mean spheres of
# truck-town's slices (engine_knobs_godot.cpp's depthBiasPerSplit).
variant godot biasscale '.bias.constantScale = [1.0, 1.4955, 3.0999, 5.7078]'
# Godot: soft low's 4 Vogel taps rotated per pixel, radius 2 texels in every split.
variant godot vogel '.filter = {kind: "pcf-vogel", vogelTaps: 4, radius: 2.0}'
pair godot-3maps godot-3c godot-3c-as4
pair godot-pancake godot-base godot-scenebounds
pair godot-biasscale godot-base godot-biasscale
pair godot-vogel godot-base godot-vogel

# Unity: map vs interval selection (one cascade: nothing to select).
variant unity interval '.cascades.selection = "interval"'
# Unity: the raster slope bias on the steeper map axis is 1/sqrt 2..1 of shadowtune's tan: the lower end.
variant unity slope-axis '.bias.slope = 1.767767'
# Unity: soft shadows Medium (biases x 2.5): the 5x5 tent against a 5x5 box and a 5x5 Gaussian.
variant unity tent5 '.filter = {kind: "pcf-tent", size: 5} | .bias.constant = 0.14396068 | .bias.normalOffset = 2.5'
variant unity box5 '.filter = {kind: "pcf-nxn", size: 5, weights: "box"} | .bias.constant = 0.14396068 | .bias.normalOffset = 2.5'
variant unity gauss5 '.filter = {kind: "pcf-nxn", size: 5, weights: "gaussian"} | .bias.constant = 0.14396068 | .bias.normalOffset = 2.5'
pair unity-selection unity-base unity-interval
pair unity-slope unity-base unity-slope-axis
pair unity-soft unity-tent5 unity-box5 unity-gauss5

# Unreal: the depth bias in each cascade's texels (constantScale) against one value.
variant unreal noscale '.bias.constantScale = []'
# Unreal: the slope term clamped at tan 1: 3.75 / tan 60 deg = UE's on level ground under the 30 deg
# sun; 0 = below UE's at every angle.
variant unreal slope-ground '.bias.slope = 2.165064'
variant unreal slope0 '.bias.slope = 0'
pair unreal-scale unreal-base unreal-noscale
pair unreal-slope unreal-base unreal-slope-ground unreal-slope0

# Filament: the normal offset x sin(angle to the light) lies between 0 and shadowtune's 0.5.
variant filament normal0 '.bias.normalOffset = 0'
pair filament-normal filament-base filament-normal0

# Bevy: no approximation of its row cells is switchable here; its base is measured for reference.
pair bevy-base bevy-base

{
    printf 'pair\tpreset\tmisclassified%%\tsoftFilteredError\tmodelMs\n'
    for m in "$OUT"/*/*/metrics.json; do
        d=$(dirname "$m")
        jq -r --arg pair "$(basename "$(dirname "$d")")" --arg p "$(basename "$d")" \
            '[$pair, $p, (.accuracy.misclassified * 100 | tostring), (.soft.filteredError | tostring), (.cost.modelMs | tostring)] | @tsv' "$m"
    done
} | tee "$OUT/summary.tsv"
