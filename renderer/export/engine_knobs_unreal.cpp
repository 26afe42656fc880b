// Unreal Engine 5's cascaded shadow maps of a movable DirectionalLight (virtual shadow maps off): the
// light's properties (UE's own names, distances in cm) and four console variables, as knobs and as
// shadowtune settings. Epic's repository is private: read from the UE 5.3-5.5 API reference and
// public copies of the files (docs/engines.md "Unreal Engine 5" names them; no commit to cite):
// DirectionalLightComponent.cpp (the constructor's defaults; GetSplitDistance with
// ComputeAccumulatedScale: renderer/export/unreal_splits.h), ShadowRendering.cpp (UpdateShaderDepthBias:
// the CSM depth bias r.Shadow.CSMDepthBias 10 x ShadowBias x the cascade's world texel scale, half a
// texel, with ShadowCascadeBiasDistribution 1; the slope bias that depth bias x
// r.Shadow.CSMSlopeScaleDepthBias 3 x ShadowSlopeBias), ShadowDepthVertexShader.usf (the slope term
// on the caster, tan clamped at r.Shadow.ShadowMaxSlopeScaleDepthBias 1) and r.ShadowQuality's help
// ("0:off, 1:low(unfiltered), 2:low .. 5:max"). Unreal does not run here: this model is a reading of
// those sources, never measured against the engine.
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"
#include "renderer/export/unreal_splits.h"
#include "renderer/settings/number_text.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

// ShadowRendering.cpp: the depth bias in texels per unit of ShadowBias (10 x half a texel), and the
// slope bias in texels x tan per unit of ShadowBias x ShadowSlopeBias (that x 3).
constexpr double kUnrealDepthTexelsPerBias = 5.0;
constexpr double kUnrealSlopeTexelsPerBias = 15.0;

json unrealDefaults() {
    return {{"DynamicShadowCascades", 3},          {"DynamicShadowDistanceMovableLight", 20000.0},
            {"CascadeDistributionExponent", 3.0},  {"CascadeTransitionFraction", 0.1},
            {"ShadowDistanceFadeoutFraction", 0.1}, {"ShadowBias", 0.5},
            {"ShadowSlopeBias", 0.5},              {"r.Shadow.MaxCSMResolution", 2048},
            {"r.ShadowQuality", 5}};
}

// r.ShadowQuality 1 unfiltered, 2 a 2x2, 3 a 3x3, 4 and 5 a 5x5 PCF (approximate: the kernels are read
// from public copies of ShadowFilteringCommon.ush, not confirmed in Epic's source).
void unrealFilter(FilterSettings& f, int quality) {
    f = FilterSettings{};
    f.kind = quality <= 1 ? FilterKind::Hard : quality == 2 ? FilterKind::Pcf2x2 : FilterKind::PcfNxN;
    if (quality >= 4) f.size = 5;
}

bool unrealPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

json unrealDefaultKnobs() { return unrealDefaults(); }

Settings unrealModel(const json& given, const Settings& view) {
    const json k = withDefaults(unrealDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = knobInt(k, "DynamicShadowCascades", 1, kMaxCascades);  // UE takes up to 10; shadowtune draws 8
    const float distance = knobFloat(k, "DynamicShadowDistanceMovableLight", 10.0, 1e9) / 100.0f;  // cm
    const float end = std::min(distance, view.camera.farPlane);
    c.shadowDistance = distance < view.camera.farPlane ? distance : 0.0f;
    c.scheme = SplitScheme::Manual;
    const double exponent = knobFloat(k, "CascadeDistributionExponent", 1.0, 4.0);  // the property's clamp
    const float near = view.camera.nearPlane;
    for (int i = 1; i < c.count; ++i)
        c.manualSplits.push_back(near + float(accumulatedScale(exponent, i, c.count)) * (end - near));
    const int resolution = knobInt(k, "r.Shadow.MaxCSMResolution", 128, 8192);
    if (!unrealPowerOfTwo(resolution))
        throw std::invalid_argument("settings.r.Shadow.MaxCSMResolution: " + std::to_string(resolution) + " is not a power of two");
    c.mapSize = resolution;
    c.fit = FitMode::Sphere;  // GetShadowSplitBounds: a bounding sphere per cascade, texel-snapped
    c.stabilize = true;
    c.zExtension = ZExtension::SceneBounds;  // casters toward the light kept by culling (approximate)
    c.selection = Selection::Interval;
    // UE blends past each split over this fraction of the cascade's range, shadowtune before it
    // (approximate); the far fade is a share of the whole shadow distance.
    c.blendBand = knobFloat(k, "CascadeTransitionFraction", 0.0, 1.0);
    const float fadeout = knobFloat(k, "ShadowDistanceFadeoutFraction", 0.0, 1.0);
    const float lastStart = c.manualSplits.empty() ? near : c.manualSplits.back();
    c.fadeBand = fadeout <= 0.0f ? 0.0f : std::min(1.0f, fadeout * end / (end - lastStart));
    unrealFilter(s.filter, knobInt(k, "r.ShadowQuality", 1, 5));
    const PresetFacts facts = presetFacts(s);
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    const float shadowBias = knobFloat(k, "ShadowBias", 0.0, 10.0);
    b.constant = float(kUnrealDepthTexelsPerBias * shadowBias * facts.texel.front());
    b.constantUnit = BiasUnit::Metres;
    if (c.count > 1 && b.constant > 0.0f)  // ShadowCascadeBiasDistribution 1: in each cascade's texels
        for (float t : facts.texel) b.constantScale.push_back(t / facts.texel.front());
    // Approximate: UE clamps tan at 1 (r.Shadow.ShadowMaxSlopeScaleDepthBias), shadowtune at 10.
    b.slope = float(kUnrealSlopeTexelsPerBias * shadowBias * knobFloat(k, "ShadowSlopeBias", 0.0, 10.0));
    b.normalOffset = 0.0f;  // UE's CSM has no normal-offset bias
    return s;
}

namespace {

void unrealCascadeKnobs(json& k, const Settings& s, const PresetFacts& f, std::vector<std::string>& lacks) {
    const CascadeSettings& c = s.cascades;
    k["DynamicShadowCascades"] = c.count;
    k["DynamicShadowDistanceMovableLight"] = round6(double(f.end) * 100.0);
    if (c.count > 1) {
        // The exponent within the property's clamp, and how far its splits lie from the preset's.
        const std::vector<double> fr = fractionsOfRange(f);
        const double exponent = round6(std::clamp(fitDistributionExponent(fr, c.count).exponent, 1.0, 4.0));
        k["CascadeDistributionExponent"] = exponent;
        double worst = 0.0;
        for (std::size_t i = 0; i < fr.size(); ++i)
            worst = std::max(worst, std::abs(fr[i] - accumulatedScale(exponent, int(i) + 1, c.count)));
        const double offMetres = worst * (double(f.end) - f.nearPlane);
        if (offMetres > 0.05)
            lacks.push_back("splits off UE's geometric distribution (exponent 1 .. 4) by up to " + formatNumber(round6(offMetres)) + " m");
    }
    if (!unrealPowerOfTwo(c.mapSize) || c.mapSize < 128 || c.mapSize > 8192)
        lacks.push_back("map size " + std::to_string(c.mapSize) + ": r.Shadow.MaxCSMResolution takes a power of two");
    k["r.Shadow.MaxCSMResolution"] = c.mapSize;
    if (c.fit != FitMode::Sphere || !c.stabilize) lacks.push_back("fit '" + enumName(c.fit) + "': UE fits a snapped sphere per cascade");
    if (c.zExtension != ZExtension::SceneBounds) lacks.push_back("z extension '" + enumName(c.zExtension) + "': UE keeps every caster toward the light");
    if (c.selection != Selection::Interval) lacks.push_back("map-based cascade selection: UE picks by view depth");
    if (c.casterFaces != CasterFaces::Both) lacks.push_back("caster faces '" + enumName(c.casterFaces) + "': not a setting of UE's lights");
    k["CascadeTransitionFraction"] = round6(c.blendBand);
    k["ShadowDistanceFadeoutFraction"] = fadeShareOfEnd(s, f);
}

int unrealQualityOf(const FilterSettings& f, std::vector<std::string>& lacks) {
    if (f.kind == FilterKind::Hard) return 1;
    if (f.kind == FilterKind::Pcf2x2) return 2;
    if (f.kind == FilterKind::PcfNxN && f.weights == FilterWeights::Box && f.size <= 5) return f.size <= 3 ? 3 : 5;
    lacks.push_back("filter '" + enumName(f.kind) + "': UE's CSM filters with a 2x2, 3x3 or 5x5 PCF (r.ShadowQuality)");
    return 5;
}

void unrealBiasKnobs(json& k, const Settings& s, const PresetFacts& f, std::vector<std::string>& lacks) {
    const BiasSettings& b = s.bias;
    if (b.constantUnit != BiasUnit::Metres) lacks.push_back("a bias in the box's depth: UE's is in texels of each cascade");
    // Within the properties' clamps (0 .. 10), so the knobs always load; beyond is listed.
    const double shadowBias = std::min(10.0, std::max(0.0f, b.constant) / (kUnrealDepthTexelsPerBias * f.texel.front()));
    if (b.constant > kUnrealDepthTexelsPerBias * 10.0 * f.texel.front()) lacks.push_back("a depth bias above ShadowBias 10");
    k["ShadowBias"] = round6(shadowBias);
    if (b.constant < 0.0f) lacks.push_back("a bias away from the light");
    if (b.constant > 0.0f && !factorsFollowTexels(b.constantScale, f))
        lacks.push_back("a constant bias per cascade other than its texel: UE's bias is in each cascade's texels");
    const double slopeBias = shadowBias > 0.0 ? b.slope / (kUnrealSlopeTexelsPerBias * shadowBias) : 0.0;
    if (slopeBias > 10.0) lacks.push_back("a slope bias above ShadowSlopeBias 10 x ShadowBias");
    if (shadowBias > 0.0) k["ShadowSlopeBias"] = round6(std::min(10.0, slopeBias));
    else if (b.slope > 0.0f) lacks.push_back("a slope bias without a depth bias: UE's slope bias is a multiple of ShadowBias");
    if (b.normalOffset > 0.0f) lacks.push_back("normal offset: UE's CSM has none");
    if (!b.slopeScale.empty() || !b.normalOffsetScale.empty()) lacks.push_back("slope or normal bias per cascade");
    if (b.receiverPlane) lacks.push_back("receiver-plane bias");
}

}  // namespace

EngineKnobs unrealKnobsFor(const Settings& s) {
    EngineKnobs out{unrealDefaults(), {}};
    const PresetFacts f = presetFacts(s);
    unrealCascadeKnobs(out.knobs, s, f, out.lacks);
    out.knobs["r.ShadowQuality"] = unrealQualityOf(s.filter, out.lacks);
    unrealBiasKnobs(out.knobs, s, f, out.lacks);
    return out;
}

const KnobTable& unrealTable() {
    static const KnobTable table{
        unrealDefaultKnobs, unrealModel, unrealKnobsFor, unrealSnippets,
        {{"DynamicShadowDistanceMovableLight", "cm"}, {"CascadeTransitionFraction", "share of a cascade"},
         {"ShadowDistanceFadeoutFraction", "share of shadow distance"}, {"ShadowBias", "x 5 texels"},
         {"ShadowSlopeBias", "x ShadowBias x 3 x tan"}, {"r.Shadow.MaxCSMResolution", "texels"}},
        // The DirectionalLight's shadow properties and the CSM console variables.
        {"cascades.count", "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize", "cascades.blendBand",
         "cascades.fadeBand", "filter.kind", "filter.size", "bias.constant", "bias.slope"}};
    return table;
}

}  // namespace st::xport
