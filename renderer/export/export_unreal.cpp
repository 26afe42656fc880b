// Unreal Engine 5, non-virtual cascaded shadow maps of a movable DirectionalLight.
// Sources (docs/engines.md: Epic's repository is private; the API reference pages and public copies of
// the files found by code search): Engine/Source/Runtime/Engine/Private/Components/
// DirectionalLightComponent.cpp (UDirectionalLightComponent constructor: the defaults;
// FDirectionalLightSceneProxy::GetSplitDistance and ComputeAccumulatedScale: the split positions),
// Renderer/Private/ShadowRendering.cpp (r.Shadow.MaxCSMResolution, r.Shadow.CSMDepthBias 10,
// r.Shadow.CSMSlopeScaleDepthBias 3, r.Shadow.CSMReceiverBias 0.9; UpdateShaderDepthBias:
// ShaderSlopeDepthBias = DepthBias x SlopeScaleDepthBias, ShaderMaxSlopeDepthBias =
// r.Shadow.ShadowMaxSlopeScaleDepthBias 1) and Shaders/Private/ShadowDepthVertexShader.usf (the slope
// term: clamp(tan, 0, max slope) x ShaderSlopeDepthBias on the caster). UE works in cm.
#include "renderer/export/unreal_splits.h"

#include "renderer/export/export_common.h"
#include "renderer/settings/number_text.h"

#include <algorithm>

namespace st::xport {
namespace {

using M = Mapping;

// r.Shadow.CSMDepthBias default 10 (ShadowRendering.cpp), x ShadowBias, x the cascade's
// world-space texel scale (bounds radius / resolution = half a texel): 10 * 0.5 * r / res
// = 2.5 texels at the defaults. As texels per unit of ShadowBias: 10 / 2 = 5.
constexpr double kCsmDepthBiasTexelsPerUnit = 5.0;
constexpr double kCsmSlopeScaleDepthBias = 3.0;     // r.Shadow.CSMSlopeScaleDepthBias default
constexpr double kShadowMaxSlopeScaleDepthBias = 1.0;  // r.Shadow.ShadowMaxSlopeScaleDepthBias default

void addSplits(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const int n = s.cascades.count;
    e.add("DynamicShadowCascades", n, M::Exact, "cascades.count (capped by r.Shadow.CSM.MaxCascades, default 10)");
    e.add("DynamicShadowDistanceMovableLight", round6(f.end * 100.0), M::Exact,
          "cascades.shadowDistance (or the camera far) in cm");
    const std::vector<double> fr = fractionsOfRange(f);
    const ExponentFit fit = fitDistributionExponent(fr, n);
    const double errorMetres = fit.maxError * (double(f.end) - f.nearPlane);
    e.add("CascadeDistributionExponent", round6(fit.exponent), errorMetres <= 0.01 ? M::Exact : M::Approximated,
          n < 2 ? "one cascade: no splits (UE's default 3 kept)"
                : "least-squares fit of ComputeAccumulatedScale (split i at near + sum_{j<i} E^j / sum_{j<N} E^j "
                  "x (distance - near)) to the preset's splits; worst split off by " +
                      formatNumber(round6(errorMetres)) + " m");
    e.add("CascadeTransitionFraction", round6(s.cascades.blendBand), M::Approximated,
          "UE extends each cascade past its split by this fraction of its depth range and fades there; "
          "shadowtune's blendBand fades inside the last fraction");
    e.add("r.Shadow.MaxCSMResolution", s.cascades.mapSize, M::Exact, "cascades.mapSize: every cascade gets this size");
}

void addBias(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const BiasSettings& b = s.bias;
    const double shadowBias = b.constant / (kCsmDepthBiasTexelsPerUnit * f.texel.front());
    e.add("ShadowBias", round6(shadowBias), M::Approximated,
          "bias.constant / (5 texels, texel " + texelNote(f) +
              "): UE's CSM depth bias = r.Shadow.CSMDepthBias 10 x ShadowBias x half a texel, per cascade");
    // UpdateShaderDepthBias: ShaderSlopeDepthBias = DepthBias x r.Shadow.CSMSlopeScaleDepthBias x ShadowSlopeBias,
    // so UE's slope bias is a multiple of its constant one: constant x 3 x ShadowSlopeBias x min(tan, 1) =
    // 5 ShadowBias x 3 ShadowSlopeBias texels x min(tan, 1); shadowtune's is bias.slope texels x tan.
    if (shadowBias > 0.0)
        e.add("ShadowSlopeBias", round6(b.slope / (kCsmDepthBiasTexelsPerUnit * kCsmSlopeScaleDepthBias * shadowBias)),
              M::Approximated,
              "bias.slope / (ShadowBias x 5 x r.Shadow.CSMSlopeScaleDepthBias 3): UE's slope bias is its constant bias "
              "x 3 x ShadowSlopeBias x tan, with tan clamped at r.Shadow.ShadowMaxSlopeScaleDepthBias 1");
    else
        e.add("ShadowSlopeBias", 0.5, b.slope > 0.0f ? M::NoEquivalent : M::Exact,
              b.slope > 0.0f ? "UE's slope bias is a multiple of its constant bias, which this preset leaves at 0; "
                               "UE's default 0.5 kept (it then adds nothing)"
                             : "no slope bias, as this preset's; UE's default 0.5 kept (with ShadowBias 0 it adds nothing)");
    e.add("r.Shadow.ShadowMaxSlopeScaleDepthBias", kShadowMaxSlopeScaleDepthBias, M::NoEquivalent,
          "UE's default: the slope bias stops growing at tan 1 (45 degrees); shadowtune's grows to tan 10");
    e.add("r.Shadow.CSMReceiverBias", 0.9, M::NoEquivalent,
          "UE's default (\"Receiver bias used by CSM. Value between 0 and 1\"); reimplementations of UE's projection "
          "shader read it as the width of a soft depth-compare transition at grazing angles (not confirmed in Epic's "
          "source); shadowtune's test is a plain compare");
    if (b.normalOffset > 0.0f)
        e.add("(normal offset)", round6(b.normalOffset), M::NoEquivalent, "UE's CSM has no user normal-offset bias");
    const FilterKind k = s.filter.kind;
    if (k == FilterKind::Pcss) {
        e.add("r.Shadow.FilterMethod", 1, M::Approximated,
              "1 = PCSS (experimental in UE): blocker search and a penumbra from the light's source angle");
        e.add("LightSourceAngle", round6(s.light.angularDiameter), M::Exact,
              "light.angularDiameter: UE's angular diameter of the light in degrees (its default 0.5357 is the sun)");
    } else {
        e.add("r.Shadow.FilterMethod", 0, k == FilterKind::PcfNxN ? M::Approximated : M::NoEquivalent,
              "0 = PCF; UE's kernel is set by r.ShadowQuality (default 5), not by a tap count");
    }
    if (isMomentFilter(k))
        e.add("(" + filterKindText(s) + ")", true, M::NoEquivalent, "UE's cascaded shadow maps have no moment filter");
}

}  // namespace

EngineExport exportUnreal(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::Unreal, "Unreal Engine 5: DirectionalLight cascaded shadow maps (non-virtual)", {}};
    addSplits(e, s, f);
    addBias(e, s, f);
    const CascadeSettings& c = s.cascades;
    e.add("(cascade fit)", "bounding sphere, texel-snapped", c.fit == FitMode::Sphere && c.stabilize ? M::Approximated
                                                                                                     : M::NoEquivalent,
          "UE fits each cascade's bounding sphere and snaps it; other fits cannot be set");
    // ShadowDistanceFadeoutFraction: the fade at the far end, a fraction of the dynamic shadow distance.
    e.add("ShadowDistanceFadeoutFraction", fadeShareOfEnd(s, f), c.fadeBand > 0.0f ? M::Approximated : M::Exact,
          c.fadeBand > 0.0f ? "cascades.fadeBand x the last cascade's range / shadow distance"
                            : "0: no fade, as this preset's (no cascades.fadeBand; UE's default 0.1)");
    // LightComponent.h: ContactShadowLength, a screen-space march from each pixel toward the light (0 =
    // off), in screen fractions unless ContactShadowLengthInWS, then in world units (cm).
    if (s.filter.contact != ContactShadows::Off) {
        e.add("ContactShadowLength", round6(s.filter.contactLength * 100.0), M::Approximated,
              "filter.contactLength in cm; UE marches its own step count and thickness (filter.contactSteps, "
              "filter.contactThickness have no setting)");
        e.add("ContactShadowLengthInWS", true, M::Exact, "the length is in world units, as filter.contactLength");
    }
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "",  // below: UE5 is camera-relative whatever the preset says
         .fitFovY = "UE fits each cascade to the camera's current field of view",
         .contact = ""});
    if (c.cameraRelative)
        e.add("(camera-relative light space)", true, M::Exact,
              "cascades.cameraRelative: UE5 renders in translated world space (large world coordinates), relative "
              "to the camera, always; no setting");
    addShadowtuneOnly(e, s, true);
    e.add("r.Shadow.Virtual.Enable", 0, M::Exact, "virtual shadow maps off: the cascaded path these settings drive");
    return e;
}

}  // namespace st::xport
