// Godot 4: DirectionalLight3D properties and the directional shadow project settings.
// Sources (godotengine/godot; docs/engines.md lists the commits and the statements read):
// scene/3d/light_3d.cpp (Light3D and DirectionalLight3D constructors: the defaults; the pancake
// property's range 0..1024 in steps of 0.1), servers/rendering/renderer_scene_cull.cpp
// _light_instance_setup_directional_shadow (split distances; each split's sphere: the mean of the
// slice's 8 corners, the farthest corner as radius, widened by a texel each side; 2-texel snapping;
// bias_scale = 2 r + pancake), servers/rendering/renderer_rd/storage_rd/light_storage.cpp
// update_light_buffers (soft_shadow_scale = shadow_blur x the quality radius without PCSS;
// shadow_bias[j] = shadow_bias / 100 x bias_scale x soft_shadow_scale; shadow_normal_bias[j] =
// normal_bias x texel; the fade from fade_start x max_distance), renderer_scene_render_rd.cpp
// (directional_soft_shadow_filter_set_quality: the quality radius 1, 1.5, 2, 2, 3, 4;
// _render_shadow_pass: use_pancake = pancake_size > 0).
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

#include <algorithm>

namespace st::xport {
namespace {

using M = Mapping;

// directional_shadow_pancake_size: the light box reaches this far toward the sun beyond the split's
// sphere, and any size above 0 also clamps the casters in front onto the box's near plane; 0 turns
// the clamp off (renderer_scene_render_rd.cpp _render_shadow_pass: use_pancake = pancake_size > 0).
struct Pancake {
    double size = 0.0;
    std::string note;
};

Pancake pancakeOf(const CascadeSettings& c) {
    switch (c.zExtension) {
        case ZExtension::None:
            return {0.0, "z extension 'none': no reach toward the sun and no clamp, as Godot's 0 (which turns pancaking "
                         "off); Godot's box still reaches to its sphere, a little past the slice"};
        case ZExtension::Distance:
            return {c.zExtensionDistance,
                    "z extension 'distance' " + formatFloat(c.zExtensionDistance) +
                        " m: the same reach; Godot also clamps the casters beyond it onto the box's near plane, which "
                        "shadowtune's 'distance' clips"};
        case ZExtension::Pancake:
            return {0.1, "z extension 'pancake' clamps the casters in front onto the slice's near plane with no reach; "
                         "Godot clamps only when the size is above 0 (0 turns it off), so the smallest step of its "
                         "editor, 0.1 m, keeps the clamp"};
        case ZExtension::SceneBounds: break;
    }
    return {20.0, "z extension 'scene-bounds': Godot has no reach to the scene's bounds; its default 20 m kept (and its "
                  "clamp beyond it)"};
}

// directional_shadow/soft_shadow_filter_quality for the preset's filter: 0 hard .. 5 ultra.
int softShadowQuality(const Settings& s) {
    const bool taps = fieldApplies(s, "filter.size");  // the kinds that spread filter.size^2 taps
    return taps ? std::min(5, s.filter.size / 2 + 1) : isMomentFilter(s.filter.kind) ? 2 : 0;
}

// renderer_scene_render_rd.cpp directional_soft_shadow_filter_set_quality: directional_shadow_quality_radius
// of each quality, which multiplies shadow_blur into soft_shadow_scale (and the depth bias) without PCSS.
constexpr double kQualityRadius[6] = {1.0, 1.5, 2.0, 2.0, 3.0, 4.0};

void addSplits(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const int n = s.cascades.count;
    const int mode = n == 1 ? 0 : n == 2 ? 1 : 2;  // SHADOW_ORTHOGONAL, PARALLEL_2_SPLITS, PARALLEL_4_SPLITS
    const bool exactMode = n == 1 || n == 2 || n == 4;
    e.add("directional_shadow_mode", mode, exactMode ? M::Exact : M::Approximated,
          exactMode ? "cascades.count " + std::to_string(n)
          : n == 3
              ? "cascades.count 3 cannot be expressed: Godot has 1, 2 or 4 splits only (a 2- or 4-split mode never draws 3 "
                "maps); exported as 4 splits, the preset's last cascade cut in two by directional_shadow_split_3"
              : "Godot has at most 4 splits; cascades.count " + std::to_string(n) +
                    " exported as 4, the preset's cascades 4.." + std::to_string(n) + " merged into the fourth split");
    // distances[i+1] = near + split_i * (max - near) (renderer_scene_cull.cpp), so split_i is a
    // fraction of the range from the camera near plane, not of the whole distance.
    const std::vector<double> fr = fractionsOfRange(f);
    const char* names[3] = {"directional_shadow_split_1", "directional_shadow_split_2", "directional_shadow_split_3"};
    const double godotDefaults[3] = {0.1, 0.2, 0.5};  // light_3d.cpp PARAM_SHADOW_SPLIT_1..3_OFFSET
    const int used = n == 2 ? 1 : n >= 3 ? 3 : 0;     // the splits Godot's mode reads
    for (int i = 0; i < 3; ++i) {
        const std::string exact = "(z" + std::to_string(i + 1) + " - near) / (max_distance - near)";
        if (i >= used)
            e.add(names[i], godotDefaults[i], M::NoEquivalent, "unused with this cascade count; Godot's default kept");
        else if (i < int(fr.size()))
            e.add(names[i], fr[size_t(i)], M::Exact, exact);
        else  // 3 cascades: split_3 (between Godot's third and fourth maps) has no counterpart
            e.add(names[i], round6(0.5 * (fr.back() + 1.0)), M::Approximated,
                  "the preset has no third split: halfway between split_2 and max_distance, so Godot's splits 3 and 4 "
                  "share the preset's last cascade (each with a map of its own)");
    }
    e.add("directional_shadow_max_distance", round6(f.end), M::Exact,
          "cascades.shadowDistance (or the camera far plane when 0); Godot ends at min(max_distance, camera far)");
}

void addFit(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const CascadeSettings& c = s.cascades;
    const int atlas = c.count == 1 ? c.mapSize : c.mapSize * 2;  // 4 splits: one quadrant each
    e.add("rendering/lights_and_shadows/directional_shadow/size", atlas,
          c.count == 1 || c.count == 4 ? M::Exact : M::Approximated,
          c.count == 2   ? "2 splits share the atlas as two size x size/2 rects; shadowtune's maps are square"
          : c.count == 3 ? "four quadrants of cascades.mapSize " + std::to_string(c.mapSize) +
                               ": Godot draws 4 maps where the preset draws 3"
                         : "cascades.mapSize " + std::to_string(c.mapSize) + " per split");
    const Pancake p = pancakeOf(c);
    e.add("directional_shadow_pancake_size", round6(p.size), M::Approximated, p.note);
    e.add("directional_shadow_blend_splits", c.blendBand > 0.0f && fieldApplies(s, "cascades.blendBand"), M::Approximated,
          "Godot blends across the whole overlap with the previous split; shadowtune's blendBand " +
              formatFloat(c.blendBand) + " blends a fraction of each cascade");
    const bool godotLike = c.fit == FitMode::Sphere && c.stabilize;
    e.add("(split fit)", "sphere around the slice's corners, snapped to 2 texels", godotLike ? M::Approximated : M::NoEquivalent,
          godotLike ? "shadowtune's sphere is the smallest around the slice (radius rounded up to 1/16 m), snapped to one "
                      "texel; Godot's is centred on the mean of the slice's 8 corners with the farthest as radius, widened "
                      "by a texel each side and snapped to 2-texel steps"
                    : "Godot always fits a snapped sphere; this preset's fit cannot be set in Godot");
    (void)f;
}

void addBias(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const BiasSettings& b = s.bias;
    const FilterKind k = s.filter.kind;
    const bool pcss = k == FilterKind::Pcss;
    const int quality = softShadowQuality(s);
    // Godot's depth bias in metres = shadow_bias / 100 x bias_scale x soft_shadow_scale, bias_scale = 2 r +
    // pancake (2 r ~ texel x split size), soft_shadow_scale = shadow_blur (1) x the quality radius, which
    // PCSS (light_angular_distance > 0) leaves out.
    const double depthRange = double(f.texel.front()) * s.cascades.mapSize + pancakeOf(s.cascades).size;
    const double softScale = pcss ? 1.0 : kQualityRadius[quality];
    e.add("shadow_bias", round6(100.0 * b.constant / (depthRange * softScale)), M::Approximated,
          "bias.constant " + formatFloat(b.constant) + " m / (light depth range of cascade 0 = " +
              formatNumber(round6(depthRange)) + " m) / (shadow_blur 1 x quality radius " + formatNumber(softScale) +
              (pcss ? ", none with PCSS" : "") +
              ") * 100; Godot's bias grows with each split's depth range and with the soft filter's radius");
    e.add("shadow_blur", 1.0, M::Approximated,
          "Godot's default: it widens the soft filter and multiplies the depth bias with it; shadow_bias above assumes 1");
    e.add("shadow_normal_bias", round6(b.normalOffset), M::Approximated,
          "texels of the split, as bias.normalOffset; Godot keeps only the part across the light direction (sin of the "
          "angle to the sun times the offset on lit faces, less on faces turned away), shadowtune moves the whole "
          "offset along the normal");
    e.add("rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality", quality, M::Approximated,
          "0 hard (one hardware-compared tap, like pcf2x2), 2 soft low (Godot's default) .. 5 ultra: Vogel disk taps "
          "rotated per pixel, radius shadow_blur x " + formatNumber(kQualityRadius[quality]) +
              " texels shrunk by split_0 / split_i in the later splits, not an NxN grid");
    if (isMomentFilter(k))
        e.add("(" + filterKindText(s) + ")", true, M::NoEquivalent, "Godot 4 has no moment shadow maps; soft PCF is the nearest");
    // DirectionalLight3D.light_angular_distance: the light's angular size in degrees; above 0 Godot
    // runs PCSS (a blocker search, a penumbra growing with distance to the blocker).
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
          fades ? "1 - cascades.fadeBand x the last cascade's range / max_distance: where Godot's fade begins; Godot "
                  "fades with a smoothstep over view depth, shadowtune linearly"
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
