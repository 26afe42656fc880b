// Bevy: CascadeShadowConfig, DirectionalLight, DirectionalLightShadowMap and the camera's ContactShadows.
// Sources (bevyengine/bevy; docs/engines.md lists the commit and lines): crates/bevy_light/src/cascade.rs
// (CascadeShadowConfig's public fields bounds, overlap_proportion, minimum_distance: any split list;
// CascadeShadowConfigBuilder::default and calculate_cascade_bounds, which space the later bounds
// geometrically; build_directional_light_cascades: cascade i starts at (1 - overlap_proportion) x the
// previous far bound), crates/bevy_pbr/src/render/light.rs (MAX_CASCADES_PER_LIGHT 4: the bounds past
// the fourth are dropped with a warning; normal bias x sqrt 2), crates/bevy_light/src/directional_light.rs
// (DEFAULT_SHADOW_DEPTH_BIAS, DEFAULT_SHADOW_NORMAL_BIAS, DirectionalLightShadowMap::default,
// soft_shadow_size, contact_shadows_enabled), crates/bevy_pbr/src/render/shadows.wesl and
// shadow_sampling.wesl (both offsets applied to the receiver, in metres and in cascade texels; PCSS
// with a search region of soft_shadow_size metres), crates/bevy_pbr/src/contact_shadows.rs.
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

#include <algorithm>
#include <cmath>

namespace st::xport {
namespace {

using M = Mapping;

// crates/bevy_pbr/src/render/light.rs MAX_CASCADES_PER_LIGHT (1 on WebGL 2).
constexpr int kBevyMaxCascades = 4;

// Bevy's cascades are whatever CascadeShadowConfig.bounds lists (its fields are public; the builder
// only fills them with a geometric series), so the preset's splits go across exactly, up to 4.
void addCascades(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const int n = s.cascades.count;
    const int used = std::min(n, kBevyMaxCascades);
    std::vector<double> bounds;
    for (int i = 1; i <= used; ++i) bounds.push_back(round6(i < used ? f.splits[size_t(i)] : f.end));
    e.add("CascadeShadowConfig.bounds", numbers(bounds), n <= kBevyMaxCascades ? M::Exact : M::Approximated,
          n <= kBevyMaxCascades
              ? "the far bound of each cascade: z1 .. z" + std::to_string(n - 1) +
                    " and the end of the shadowed range; set the config's fields directly (the builder would space "
                    "the bounds after the first geometrically)"
              : "Bevy draws at most 4 cascades (MAX_CASCADES_PER_LIGHT; it warns and drops the bounds past the fourth, "
                "so shadows would end there): the preset's first 3 splits, the fourth cascade stretched to the end of "
                "the shadowed range");
    e.add("CascadeShadowConfig.minimum_distance", round6(f.nearPlane), M::Exact,
          "the camera near plane, where shadowtune's first cascade starts");
    // Bevy blends over overlap x far_k at the end of cascade k; shadowtune over blendBand x its
    // depth range (z_{k+1} - z_k). Converted on cascade 1 (cascade 0 with one or two cascades); the
    // ratio differs between cascades unless the splits are geometric.
    const size_t k = used >= 3 ? 1 : 0;
    const double overlap = used > 1 ? s.cascades.blendBand * (f.splits[k + 1] - f.splits[k]) / f.splits[k + 1] : 0.0;
    e.add("CascadeShadowConfig.overlap_proportion", round6(overlap), M::Approximated,
          "blendBand x (z" + std::to_string(k + 1) + " - z" + std::to_string(k) + ") / z" + std::to_string(k + 1) +
              "; one proportion for every cascade; Bevy's cascades also overlap in their light boxes, shadowtune's do not");
    e.add("DirectionalLightShadowMap.size", s.cascades.mapSize, M::Exact, "cascades.mapSize, per cascade");
}

void addBias(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const BiasSettings& b = s.bias;
    e.add("DirectionalLight.shadow_depth_bias", round6(b.constant), M::Exact,
          "metres toward the light, applied to the receiver, as bias.constant");
    e.add("DirectionalLight.shadow_normal_bias", round6(b.normalOffset / std::sqrt(2.0)), M::Approximated,
          "bias.normalOffset / sqrt 2 (Bevy multiplies by sqrt 2, then by its texel: ceil(diameter) / size)");
    const FilterKind k = s.filter.kind;
    // Gaussian is Castano's 9 bilinear taps over 5 x 5 texels (shadow_sampling.wesl:101-143): shadowtune's
    // tent of 5 exactly; Temporal is 8 spiral taps rotated per pixel (:173-205), nearest to the Vogel disc.
    const bool tent5 = k == FilterKind::Tent && s.filter.size == 5;
    const char* method = k == FilterKind::Vogel ? "Temporal" : (k == FilterKind::PcfNxN || k == FilterKind::Tent) ? "Gaussian" : "Hardware2x2";
    e.add("ShadowFilteringMethod", method, k == FilterKind::Pcf2x2 || tent5 ? M::Exact : M::Approximated,
          k == FilterKind::Hard    ? "Bevy has no unfiltered test; Hardware2x2 is the nearest"
          : k == FilterKind::Vogel ? "Temporal: 8 spiral taps, rotated per pixel and per frame, f(texel) metres wide"
                                   : "Gaussian: Castano's 9 bilinear taps over 5x5 texels, shadowtune's pcf-tent 5 (Bevy's default)");
    if (isMomentFilter(k))
        e.add("(" + filterKindText(s) + ")", true, M::NoEquivalent, "Bevy has no moment shadow maps");
    // shadow_sampling.wesl: the blocker search reaches soft_shadow_size x (up to 0.875) metres around the
    // receiver (uv offset = size / (texel x map size)), the blur is (z_blocker - z) x size / z in the cascade's
    // depth: a world size, not an angle, so no value gives light.angularDiameter's penumbra at every distance.
    if (k == FilterKind::Pcss)
        e.add("DirectionalLight.soft_shadow_size", round6(s.filter.pcssMaxRadius * f.texel.front()), M::Approximated,
              "metres (a world size, not an angle): the reach of shadowtune's blocker search in cascade 0, "
              "filter.pcssMaxRadius " + formatFloat(s.filter.pcssMaxRadius) + " texels x " + texelNote(f) +
                  "; Bevy's penumbra does not follow light.angularDiameter; needs the experimental_pbr_pcss feature");
    if (b.slope > 0.0f) e.add("(slope bias)", round6(b.slope), M::NoEquivalent, "Bevy has no slope-scaled bias");
    if (b.receiverPlane && fieldApplies(s, "bias.receiverPlane")) e.add("(receiver-plane bias)", true, M::NoEquivalent, "Bevy has no receiver-plane bias");
}

}  // namespace

EngineExport exportBevy(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::Bevy, "Bevy: CascadeShadowConfig and DirectionalLight", {}};
    addCascades(e, s, f);
    addBias(e, s, f);
    const CascadeSettings& c = s.cascades;
    e.add("(cascade fit)", "diameter-sized box, texel-snapped, depth-clamped",
          (c.fit == FitMode::Diagonal || c.fit == FitMode::Sphere) && c.stabilize && c.zExtension == ZExtension::Pancake
              ? M::Approximated
              : M::NoEquivalent,
          "Bevy always sizes a cascade by its slice's longer diagonal (far face or body) rounded up to whole metres, "
          "floors its centre to texels and pancakes casters (unclipped depth; cascade.rs:284-299): shadowtune's "
          "diagonal fit with the centre floored, without the rounding (a sphere is at least as wide)");
    // crates/bevy_pbr/src/contact_shadows.rs: a camera component (linear_steps 16, thickness 0.1, length 0.3
    // by default) and DirectionalLight.contact_shadows_enabled: a screen-space march toward the light.
    if (s.filter.contact != ContactShadows::Off) {
        e.add("DirectionalLight.contact_shadows_enabled", true, M::Exact, "filter.contact: a screen-space march toward the sun");
        e.add("ContactShadows.length", round6(s.filter.contactLength), M::Approximated,
              "filter.contactLength in metres; a component on the camera (it needs the depth prepass); Bevy's march "
              "and its refinement are its own");
        e.add("ContactShadows.linear_steps", s.filter.contactSteps, M::Approximated, "filter.contactSteps");
        e.add("ContactShadows.thickness", round6(s.filter.contactThickness), M::Approximated,
              "filter.contactThickness in metres: how thick each depth-buffer sample is assumed to be");
    }
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "Bevy fits its cascades in world space, in f32",
         .fitFovY = "Bevy fits each cascade to the camera's current projection",
         .contact = ""});
    addShadowtuneOnly(e, s, false);
    return e;
}

}  // namespace st::xport
