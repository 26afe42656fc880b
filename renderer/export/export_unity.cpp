// Unity URP: UniversalRenderPipelineAsset shadow settings.
// Sources (Unity-Technologies/Graphics; docs/engines.md lists the commits): Packages/
// com.unity.render-pipelines.universal/Runtime/Data/UniversalRenderPipelineAsset.cs (field
// initialisers: the defaults), Runtime/ShadowUtils.cs (GetShadowBias: depth and normal bias are
// multiples of the cascade's texel size, x1.5 / 2.5 / 3.5 with soft shadows of low / medium / high
// quality; RenderShadowSlice: a fixed raster bias SetGlobalDepthBias(1, 2.5) on every caster;
// GetScaleAndBiasForLinearDistanceFade), ShaderLibrary/Shadows.hlsl (ComputeCascadeIndex: the first
// cascade whose culling sphere holds the pixel; ApplyShadowBias: depth bias along the light, normal
// bias scaled by 1 - N.L, on the caster; SampleShadowmapFiltered: tent PCF 3x3 / 5x5 / 7x7).
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace st::xport {
namespace {

using M = Mapping;

void addCascades(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const int n = s.cascades.count;
    e.add("shadowCascadeCount", std::min(n, 4), n <= 4 ? M::Exact : M::Approximated,
          n <= 4 ? "cascades.count" : "URP has at most 4 cascades");
    // URP splits are fractions of the shadow distance measured from the camera.
    const std::vector<double> fr = fractionsOfEnd(f);
    auto pick = [&](size_t count, std::vector<double> urpDefault) {
        return fr.size() + 1 == count ? std::pair{numbers(fr), M::Exact} : std::pair{numbers(urpDefault), M::NoEquivalent};
    };
    const auto [c2, m2] = pick(2, {0.25});
    const auto [c3, m3] = pick(3, {0.1, 0.3});
    const auto [c4, m4] = pick(4, {0.067, 0.2, 0.467});
    const char* used = "z_i / shadowDistance";
    const char* unused = "unused with this cascade count; URP's default kept";
    e.add("cascade2Split", c2.front(), m2, m2 == M::Exact ? used : unused);
    e.add("cascade3Split", c3, m3, m3 == M::Exact ? used : unused);
    e.add("cascade4Split", c4, m4, m4 == M::Exact ? used : unused);
    e.add("shadowDistance", round6(f.end), M::Exact, "cascades.shadowDistance, or the camera far plane when 0");
    // ShadowUtils: 2..4 cascades share one atlas of this size in 2x2 tiles, each half its side.
    const int atlas = n == 1 ? s.cascades.mapSize : s.cascades.mapSize * 2;
    e.add("mainLightShadowmapResolution", std::min(atlas, 8192), atlas <= 8192 ? M::Exact : M::Approximated,
          n == 1 ? "cascades.mapSize" : "2x2 tiles of cascades.mapSize in one atlas");
}

// ShadowUtils.GetShadowBias: with soft shadows both biases grow with the tent kernel's radius.
double softKernelRadius(const char* quality) {
    const std::string q(quality);
    return q == "Low" ? 1.5 : q == "High" ? 3.5 : 2.5;
}

// ShadowUtils.RenderShadowSlice: cmd.SetGlobalDepthBias(1.0f, 2.5f) around every caster draw, a raster
// slope-scaled bias of 2.5 x the caster's depth slope per texel, ~ 2.5 texels x tan in shadowtune's unit.
constexpr double kUrpRasterSlopeBias = 2.5;

void addBiasAndFilter(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const BiasSettings& b = s.bias;
    const FilterKind k = s.filter.kind;
    const bool soft = k != FilterKind::Hard && k != FilterKind::Pcf2x2;  // URP's only filtered mode is soft
    const char* quality = k != FilterKind::PcfNxN || s.filter.size > 5 ? "High" : s.filter.size <= 3 ? "Low" : "Medium";
    const double kernel = soft ? softKernelRadius(quality) : 1.0;  // ShadowUtils.GetShadowBias
    const std::string kernelNote = soft ? " / " + formatNumber(kernel) + " (soft shadows, " + quality + " quality)" : "";
    e.add("shadowDepthBias", round6(b.constant / (f.texel.front() * kernel)), M::Approximated,
          "bias.constant / texel " + texelNote(f) + kernelNote +
              "; URP's depth bias is a multiple of each cascade's texel, shadowtune's is metres");
    e.add("shadowNormalBias", round6(b.normalOffset / kernel), M::Approximated,
          "texels, as bias.normalOffset" + kernelNote + "; URP moves the caster inward, scaled by 1 - N.L");
    const bool pcfLike = k == FilterKind::Hard || k == FilterKind::Pcf2x2 || k == FilterKind::PcfNxN;
    e.add("supportsSoftShadows", soft, !pcfLike || k == FilterKind::Hard ? M::Approximated : M::Exact,
          k == FilterKind::Hard ? "URP's hard shadows still take one hardware-compared (2x2) tap"
          : pcfLike             ? "off: one hardware-compared tap = pcf2x2; on: tent PCF (the light's Shadow Type "
                                  "must be Soft Shadows too)"
                                : "tent PCF is the nearest URP asset setting to " + filterKindText(s));
    if (soft)
        e.add("softShadowQuality", quality, M::Approximated,
              "tent-filtered PCF (Low: 4 taps ~3x3, Medium 5x5, High 7x7), not a box of NxN taps; it also sets the "
              "bias multiplier above");
    if (!pcfLike)
        e.add("(" + filterKindText(s) + ")", true, M::NoEquivalent,
              "the URP asset has no moment (VSM/EVSM/MSM) or PCSS filter for the main light");
    const bool urpSlope = std::fabs(b.slope - kUrpRasterSlopeBias) <= 0.25;
    e.add("(slope bias)", kUrpRasterSlopeBias, urpSlope ? M::Approximated : M::NoEquivalent,
          std::string("URP has no slope-bias setting: its caster pass always adds a raster bias of 2.5 x the depth "
                      "slope (SetGlobalDepthBias(1, 2.5)), ~ bias.slope 2.5 with tan taken along the steeper map axis") +
              (urpSlope ? "" : "; this preset's bias.slope is " + formatNumber(round6(b.slope))));
    if (b.receiverPlane && fieldApplies(s, "bias.receiverPlane")) e.add("(receiver-plane bias)", true, M::NoEquivalent, "URP has no receiver-plane bias");
}

void addUnmapped(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const CascadeSettings& c = s.cascades;
    const bool stable = c.fit == FitMode::Sphere && c.stabilize;
    e.add("(cascade fit)", "stable fit: bounding sphere, texel-snapped", stable ? M::Approximated : M::NoEquivalent,
          stable ? "shadowtune's sphere fit with snapping; URP's spheres come from the engine's culling code"
                 : "URP always uses a stable sphere fit");
    // ShadowUtils.GetScaleAndBiasForLinearDistanceFade: the fade runs over squared distance from
    // ((1 - border) x shadowDistance)^2 to shadowDistance^2; border < 0.0001 cuts off there.
    const double border = fadeShareOfEnd(s, f);
    e.add("cascadeBorder", border, c.fadeBand > 0.0f ? M::Approximated : M::Exact,
          c.fadeBand > 0.0f ? "cascades.fadeBand x the last cascade's range / shadowDistance; URP fades linearly in "
                              "squared distance, shadowtune in view depth"
                            : "0: shadows end at shadowDistance, as this preset's (no cascades.fadeBand)");
    if (c.blendBand > 0.0f)
        e.add("(cascade blending)", round6(c.blendBand), M::NoEquivalent, "URP does not blend between cascades");
    // Shadows.hlsl ComputeCascadeIndex: the first cascade whose culling sphere holds the pixel.
    const char* selection = "first cascade whose culling sphere holds the pixel";
    if (c.count == 1)
        e.add("(cascade selection)", selection, M::Exact, "one cascade: nothing to select");
    else if (c.selection == Selection::Map)
        e.add("(cascade selection)", selection, M::Approximated,
              "cascades.selection 'map': the first map holding the point, as URP; shadowtune tests the map's square "
              "less the filter's margin, URP the sphere inside it");
    else
        e.add("(cascade selection)", selection, M::NoEquivalent,
              "cascades.selection 'interval' selects by view depth; URP cannot (shadowtune's 'map' is URP's rule)");
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "URP renders and fits its cascades in world space (camera-relative rendering is HDRP's)",
         .fitFovY = "URP fits each cascade's sphere to the camera's current field of view",
         .contact = "URP has no contact shadows (HDRP's Contact Shadows volume override has)"});
    addShadowtuneOnly(e, s, true);
}

}  // namespace

EngineExport exportUnity(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::Unity, "Unity URP: UniversalRenderPipelineAsset shadows", {}};
    addCascades(e, s, f);
    addBiasAndFilter(e, s, f);
    addUnmapped(e, s, f);
    return e;
}

}  // namespace st::xport
