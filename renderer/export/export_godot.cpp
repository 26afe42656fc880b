// Godot 4: DirectionalLight3D properties and the directional shadow project settings.
// Sources (godotengine/godot): scene/3d/light_3d.cpp (Light3D and DirectionalLight3D constructors:
// the defaults), servers/rendering/renderer_scene_cull.cpp _light_instance_setup_directional_shadow
// (split distances, sphere fit, texel snapping, pancake), the RD light storage (shadow_bias[j] =
// shadow_bias / 100 * the cascade's light depth range; shadow_normal_bias[j] = normal_bias * texel).
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

namespace st::xport {
namespace {

using M = Mapping;

// Godot's pancake_size: how far the light box reaches toward the sun beyond the split's sphere.
float pancakeOf(const CascadeSettings& c) {
    if (c.zExtension == ZExtension::Distance) return c.zExtensionDistance;
    if (c.zExtension == ZExtension::SceneBounds) return 20.0f;  // Godot's default: no scene-bounds mode
    return 0.0f;
}

void addSplits(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const int n = s.cascades.count;
    const int mode = n == 1 ? 0 : n == 2 ? 1 : 2;  // SHADOW_ORTHOGONAL, PARALLEL_2_SPLITS, PARALLEL_4_SPLITS
    e.add("directional_shadow_mode", mode, n == 1 || n == 2 || n == 4 ? M::Exact : M::Approximated,
          n == 1 || n == 2 || n == 4 ? "cascades.count " + std::to_string(n)
                                     : "Godot has 1, 2 or 4 splits only; cascades.count " + std::to_string(n) +
                                           " exported as 4 (the nearest above)");
    // distances[i+1] = near + split_i * (max - near) (renderer_scene_cull.cpp), so split_i is a
    // fraction of the range from the camera near plane, not of the whole distance.
    const std::vector<double> fr = fractionsOfRange(f);
    const char* names[3] = {"directional_shadow_split_1", "directional_shadow_split_2", "directional_shadow_split_3"};
    const double godotDefaults[3] = {0.1, 0.2, 0.5};  // light_3d.cpp PARAM_SHADOW_SPLIT_1..3_OFFSET
    for (int i = 0; i < 3; ++i) {
        if (i < int(fr.size()) && (n == 2 || n == 4))
            e.add(names[i], fr[size_t(i)], M::Exact, "(z" + std::to_string(i + 1) + " - near) / (max_distance - near)");
        else
            e.add(names[i], godotDefaults[i], M::NoEquivalent, "unused with this cascade count; Godot's default kept");
    }
    e.add("directional_shadow_max_distance", round6(f.end), M::Exact,
          "cascades.shadowDistance (or the camera far plane when 0); Godot ends at min(max_distance, camera far)");
}

void addFit(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const CascadeSettings& c = s.cascades;
    const int atlas = c.count == 1 ? c.mapSize : c.mapSize * 2;  // 4 splits: one quadrant each
    e.add("rendering/lights_and_shadows/directional_shadow/size", atlas,
          c.count == 1 || c.count == 4 ? M::Exact : M::Approximated,
          c.count == 2 ? "2 splits share the atlas as two size x size/2 rects; shadowtune's maps are square"
                       : "cascades.mapSize " + std::to_string(c.mapSize) + " per split");
    e.add("directional_shadow_pancake_size", round6(pancakeOf(c)), M::Approximated,
          "Godot reaches this far toward the sun beyond each split's sphere and clamps casters in front "
          "(pancaking); shadowtune's z extension '" + std::string(EnumNames<ZExtension>::names[size_t(c.zExtension)]) +
              "' does one of the two");
    e.add("directional_shadow_blend_splits", c.blendBand > 0.0f && fieldApplies(s, "cascades.blendBand"), M::Approximated,
          "Godot blends across the whole overlap with the previous split; shadowtune's blendBand " +
              formatFloat(c.blendBand) + " blends a fraction of each cascade");
    const bool godotLike = c.fit == FitMode::Sphere && c.stabilize;
    e.add("(split fit)", "bounding sphere, snapped to 2 texels", godotLike ? M::Approximated : M::NoEquivalent,
          godotLike ? "shadowtune's sphere fit with texel snapping; Godot snaps to 2-texel steps"
                    : "Godot always fits a snapped sphere; this preset's fit cannot be set in Godot");
    (void)f;
}

void addBias(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const BiasSettings& b = s.bias;
    // Godot's depth bias in metres = shadow_bias / 100 * (2 r + pancake) (2 r ~ texel * split size).
    const double depthRange = double(f.texel.front()) * s.cascades.mapSize + pancakeOf(s.cascades);
    e.add("shadow_bias", round6(100.0 * b.constant / depthRange), M::Approximated,
          "bias.constant " + formatFloat(b.constant) + " m / (light depth range of cascade 0 = " +
              formatNumber(round6(depthRange)) + " m) * 100; Godot's bias grows with each split's depth range");
    e.add("shadow_normal_bias", round6(b.normalOffset), M::Approximated,
          "texels of the split, as bias.normalOffset; Godot scales it by (1 - N.L) and drops its light-direction part");
    const FilterKind k = s.filter.kind;
    const bool taps = fieldApplies(s, "filter.size");  // the kinds that spread filter.size^2 taps
    e.add("rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality",
          taps ? std::min(5, s.filter.size / 2 + 1) : isMomentFilter(k) ? 2 : 0, M::Approximated,
          "0 hard (one hardware-compared tap, like pcf2x2), 2 soft low (Godot's default) .. 5 ultra: rotated disk "
          "taps scaled by shadow_blur, not an NxN grid");
    if (isMomentFilter(k))
        e.add("(" + filterKindText(s) + ")", true, M::NoEquivalent, "Godot 4 has no moment shadow maps; soft PCF is the nearest");
    // DirectionalLight3D.light_angular_distance: the light's angular size in degrees; above 0 Godot
    // runs PCSS (a blocker search, a penumbra growing with distance to the blocker).
    const bool pcss = k == FilterKind::Pcss;
    e.add("light_angular_distance", pcss ? round6(s.light.angularDiameter) : 0.0, pcss ? M::Approximated : M::Exact,
          pcss ? "light.angularDiameter in degrees; Godot's PCSS kernel is its own, capped by soft_shadow_filter_quality"
               : "0: no PCSS, as " + filterKindText(s));
    if (b.slope > 0.0f)
        e.add("(slope bias)", round6(b.slope), M::NoEquivalent, "Godot has no slope-scaled bias for directional lights");
    if (b.receiverPlane && fieldApplies(s, "bias.receiverPlane")) e.add("(receiver-plane bias)", true, M::NoEquivalent, "Godot has no receiver-plane bias");
}

}  // namespace

EngineExport exportGodot(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::Godot, "Godot 4: DirectionalLight3D properties and project settings", {}};
    addSplits(e, s, f);
    addFit(e, s, f);
    addBias(e, s, f);
    const bool fades = s.cascades.fadeBand > 0.0f;
    e.add("directional_shadow_fade_start", round6(1.0 - fadeShareOfEnd(s, f)), fades ? M::Approximated : M::Exact,
          fades ? "1 - cascades.fadeBand x the last cascade's range / max_distance: where Godot's fade begins"
                : "1.0: shadows cut off at max_distance, as this preset's (no cascades.fadeBand; Godot's default 0.8)");
    // godotengine/godot PR #119680 (open): DirectionalLight3D.directional_shadow_min_fov fits the splits for
    // at least this FOV, so an FOV animation below it keeps their size (godot #72015).
    if (s.cascades.fitFovY > 0.0f)
        e.add("directional_shadow_min_fov", round6(s.cascades.fitFovY), M::Approximated,
              "cascades.fitFovY in degrees; the property of godot PR #119680, not yet in a Godot release");
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "Godot fits its splits in world space; only a precision=double build (large world "
                           "coordinates) keeps precision far from the origin, no setting does",
         .fitFovY = "",
         .contact = "no property this export sets; Godot's screen-space contact shadows for directional lights "
                    "(godot PR #118045) are set by hand"});
    addShadowtuneOnly(e, s, true);
    return e;
}

}  // namespace st::xport
