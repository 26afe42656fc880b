// Bevy: CascadeShadowConfigBuilder, DirectionalLight and DirectionalLightShadowMap.
// Sources (bevyengine/bevy): crates/bevy_light/src/cascade.rs (CascadeShadowConfigBuilder::default,
// calculate_cascade_bounds: cascades after the first spaced geometrically up to maximum_distance;
// build_directional_light_cascades: cascade i starts at (1 - overlap_proportion) x the previous far
// bound), crates/bevy_light/src/directional_light.rs (DEFAULT_SHADOW_DEPTH_BIAS,
// DEFAULT_SHADOW_NORMAL_BIAS, DirectionalLightShadowMap::default), crates/bevy_pbr/src/render/
// light.rs (normal bias x sqrt 2) and shadows.wesl (both offsets applied to the receiver, in
// metres and in cascade texels).
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

#include <algorithm>
#include <cmath>

namespace st::xport {
namespace {

using M = Mapping;

// Largest distance between the preset's interior splits 2..N-1 and Bevy's geometric ones.
double geometricError(const PresetFacts& f) {
    const size_t n = f.splits.size() - 1;
    double worst = 0.0;
    for (size_t i = 1; i + 1 < n; ++i) {
        const double bevy = f.splits[1] * std::pow(double(f.end) / f.splits[1], double(i) / double(n - 1));
        worst = std::max(worst, std::fabs(bevy - f.splits[i + 1]));
    }
    return worst;
}

void addCascades(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const int n = s.cascades.count;
    e.add("CascadeShadowConfigBuilder.num_cascades", n, M::Exact, "cascades.count");
    e.add("CascadeShadowConfigBuilder.minimum_distance", round6(f.nearPlane), M::Exact,
          "the camera near plane, where shadowtune's first cascade starts");
    e.add("CascadeShadowConfigBuilder.maximum_distance", round6(f.end), M::Exact,
          "cascades.shadowDistance, or the camera far plane when 0");
    const double err = n >= 3 ? geometricError(f) : 0.0;
    e.add("CascadeShadowConfigBuilder.first_cascade_far_bound", round6(n > 1 ? f.splits[1] : f.end),
          err <= 0.01 ? M::Exact : M::Approximated,
          n == 1 ? "ignored with one cascade"
                 : "z1; Bevy spaces the later splits geometrically from it to maximum_distance" +
                       (n >= 3 ? ", off the preset's by up to " + formatNumber(round6(err)) + " m" : std::string()));
    // Bevy blends over overlap x far_k at the end of cascade k; shadowtune over blendBand x its
    // depth range (z_{k+1} - z_k). Converted on cascade 1, whose ratio every interior cascade of
    // geometric splits shares (cascade 0 with one or two cascades).
    const size_t k = n >= 3 ? 1 : 0;
    const double overlap = n > 1 ? s.cascades.blendBand * (f.splits[k + 1] - f.splits[k]) / f.splits[k + 1] : 0.0;
    e.add("CascadeShadowConfigBuilder.overlap_proportion", round6(overlap), M::Approximated,
          "blendBand x (z" + std::to_string(k + 1) + " - z" + std::to_string(k) + ") / z" + std::to_string(k + 1) +
              "; Bevy's cascades also overlap in their light boxes, shadowtune's do not");
    e.add("DirectionalLightShadowMap.size", s.cascades.mapSize, M::Exact, "cascades.mapSize, per cascade");
}

void addBias(EngineExport& e, const Settings& s) {
    const BiasSettings& b = s.bias;
    e.add("DirectionalLight.shadow_depth_bias", round6(b.constant), M::Exact,
          "metres toward the light, applied to the receiver, as bias.constant");
    e.add("DirectionalLight.shadow_normal_bias", round6(b.normalOffset / std::sqrt(2.0)), M::Approximated,
          "bias.normalOffset / sqrt 2 (Bevy multiplies by sqrt 2, then by its texel: ceil(diameter) / size)");
    const FilterKind k = s.filter.kind;
    e.add("ShadowFilteringMethod", k == FilterKind::PcfNxN ? "Gaussian" : "Hardware2x2",
          k == FilterKind::Pcf2x2 ? M::Exact : M::Approximated,
          k == FilterKind::Hard ? "Bevy has no unfiltered test; Hardware2x2 is the nearest"
                                : "Gaussian: Castano's 9-tap filter, about a 5x5 kernel (Bevy's default)");
    if (isMomentFilter(k))
        e.add("(" + filterKindText(s) + ")", true, M::NoEquivalent, "Bevy has no moment shadow maps");
    if (k == FilterKind::Pcss)
        e.add("DirectionalLight.soft_shadow_size", round6(s.light.angularDiameter * 3.14159265358979 / 180.0),
              M::Approximated,
              "light.angularDiameter in radians; Bevy's PCSS needs the experimental_pbr_pcss feature (the unit of this "
              "field is not confirmed against Bevy's shader)");
    if (b.slope > 0.0f) e.add("(slope bias)", round6(b.slope), M::NoEquivalent, "Bevy has no slope-scaled bias");
    if (b.receiverPlane && fieldApplies(s, "bias.receiverPlane")) e.add("(receiver-plane bias)", true, M::NoEquivalent, "Bevy has no receiver-plane bias");
}

}  // namespace

EngineExport exportBevy(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::Bevy, "Bevy: CascadeShadowConfigBuilder and DirectionalLight", {}};
    addCascades(e, s, f);
    addBias(e, s);
    const CascadeSettings& c = s.cascades;
    e.add("(cascade fit)", "diameter-sized box, texel-snapped, depth-clamped",
          c.fit == FitMode::Sphere && c.stabilize && c.zExtension == ZExtension::Pancake ? M::Approximated
                                                                                          : M::NoEquivalent,
          "Bevy always sizes a cascade by its slice's diagonal, snaps it and pancakes casters (unclipped depth)");
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "Bevy fits its cascades in world space, in f32",
         .fitFovY = "Bevy fits each cascade to the camera's current projection",
         .contact = "not a DirectionalLight or cascade setting this export targets (bevy #16164 tracks screen-space "
                    "contact shadows)"});
    addShadowtuneOnly(e, s, false);
    return e;
}

}  // namespace st::xport
