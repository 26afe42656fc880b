// Unity URP's main-light shadows: the shadow fields of a UniversalRenderPipelineAsset, as knobs
// (their serialized names, as the .asset file holds them) and as shadowtune settings. Read from
// Unity-Technologies/Graphics, package com.unity.render-pipelines.universal (docs/engines.md "Unity
// URP" names the commits): Runtime/Data/UniversalRenderPipelineAsset.cs (the field initialisers: the
// defaults; k_ShadowCascadeMaxCount 4), Runtime/ShadowUtils.cs (GetShadowBias: both biases are
// multiples of the cascade's texel, x the soft kernel's radius 1.5 / 2.5 / 3.5; RenderShadowSlice:
// SetGlobalDepthBias(1, 2.5) on every caster; GetScaleAndBiasForLinearDistanceFade),
// Runtime/Passes/MainLightShadowCasterPass.cs (2..4 cascades share the atlas in tiles of half its
// side), ShaderLibrary/Shadows.hlsl (ComputeCascadeIndex: the first culling sphere holding the pixel;
// SampleShadowmapFilteredLow/Medium/HighQuality), Shaders/Lit.shader (the ShadowCaster pass culls as
// the material, _Cull Back by default: front faces cast). Unity does not run here: this model is a
// reading of the source, never measured against the engine.
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

constexpr const char* kUnitySplitKeys[3] = {"m_Cascade2Split", "m_Cascade3Split", "m_Cascade4Split"};
constexpr float kUnityRasterSlopeBias = 2.5f;  // ShadowUtils.RenderShadowSlice: SetGlobalDepthBias(1, 2.5)

json unityDefaults() {
    return {{"m_ShadowDistance", 50.0},        {"m_ShadowCascadeCount", 1},
            {"m_Cascade2Split", 0.25},         {"m_Cascade3Split", {0.1, 0.3}},
            {"m_Cascade4Split", {0.067, 0.2, 0.467}}, {"m_CascadeBorder", 0.2},
            {"m_MainLightShadowmapResolution", 2048}, {"m_ShadowDepthBias", 1.0},
            {"m_ShadowNormalBias", 1.0},       {"m_SoftShadowsSupported", 0},
            {"m_SoftShadowQuality", 2}};
}

// GetShadowBias: with soft shadows both biases grow by the tent kernel's radius (Low 1, Medium 2,
// High 3 in the asset's SoftShadowQuality numbering).
float unityKernelRadius(bool soft, int quality) { return !soft ? 1.0f : quality == 1 ? 1.5f : quality == 3 ? 3.5f : 2.5f; }

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// The split fractions the count uses: m_Cascade2Split a number, 3Split and 4Split lists.
std::vector<float> unitySplitFractions(const json& k, int count) {
    std::vector<float> out;
    if (count < 2) return out;
    const char* key = kUnitySplitKeys[count - 2];
    const json& v = k.at(key);
    const json list = v.is_array() ? v : json::array({v});
    if (int(list.size()) != count - 1)
        throw std::invalid_argument(std::string("settings.") + key + ": expected " + std::to_string(count - 1) + " fractions");
    float previous = 0.0f;
    for (const json& x : list) {
        const float f = x.is_number() ? x.get<float>() : -1.0f;
        if (!(f > previous && f < 1.0f))
            throw std::invalid_argument(std::string("settings.") + key + ": " + v.dump() +
                                        " must be fractions of the shadow distance, increasing, between 0 and 1");
        out.push_back(previous = f);
    }
    return out;
}

void unityFilter(FilterSettings& f, bool soft, int quality) {
    f = FilterSettings{};
    if (!soft) return;  // one hardware-compared tap: pcf2x2, the default
    // Low: 4 bilinear compares (a 3x3 tent); Medium: the 5x5 tent of 9. Approximate for High: its
    // 7x7 tent of 16 taps is drawn as the 5x5 one (shadowtune's tent stops there).
    f.kind = FilterKind::Tent;
    f.size = quality == 1 ? 3 : 5;
}

}  // namespace

json unityDefaultKnobs() { return unityDefaults(); }

Settings unityModel(const json& given, const Settings& view) {
    const json k = withDefaults(unityDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = knobInt(k, "m_ShadowCascadeCount", 1, 4);
    const float distance = knobFloat(k, "m_ShadowDistance", 0.1, 1e7);
    const float end = std::min(distance, view.camera.farPlane);
    c.shadowDistance = distance < view.camera.farPlane ? distance : 0.0f;
    c.scheme = SplitScheme::Manual;
    for (float f : unitySplitFractions(k, c.count)) {  // fractions of the shadow distance from the camera
        if (f * end <= view.camera.nearPlane)
            throw std::invalid_argument("settings." + std::string(kUnitySplitKeys[c.count - 2]) + ": a split lies before the camera's near plane");
        c.manualSplits.push_back(f * end);
    }
    const int resolution = knobInt(k, "m_MainLightShadowmapResolution", 256, 8192);
    if (!isPowerOfTwo(resolution))
        throw std::invalid_argument("settings.m_MainLightShadowmapResolution: " + std::to_string(resolution) +
                                    " is not one of 256, 512, 1024, 2048, 4096, 8192");
    c.mapSize = c.count == 1 ? resolution : resolution / 2;  // 2..4 cascades: tiles of half the atlas
    c.fit = FitMode::Sphere;  // the culling spheres, texel-snapped (approximate: URP's come from native culling)
    c.stabilize = true;
    c.zExtension = ZExtension::SceneBounds;  // casters toward the light kept by culling, depth clamped
    c.selection = Selection::Map;            // the first culling sphere holding the pixel (approximate: a square)
    c.casterFaces = CasterFaces::Front;      // Lit.shader's ShadowCaster pass: Cull[_Cull], Back by default
    // The fade runs from (1 - border) x distance to distance (approximate: URP's is linear in the
    // squared distance, this one in view depth).
    const float border = knobFloat(k, "m_CascadeBorder", 0.0, 1.0);
    const float lastStart = c.manualSplits.empty() ? view.camera.nearPlane : c.manualSplits.back();
    c.fadeBand = border <= 0.0f ? 0.0f : std::min(1.0f, border * end / (end - lastStart));
    const bool soft = knobInt(k, "m_SoftShadowsSupported", 0, 1) == 1;
    const int quality = knobInt(k, "m_SoftShadowQuality", 1, 3);
    unityFilter(s.filter, soft, quality);
    // Both biases in texels of each cascade, x the kernel radius; they move the caster, shadowtune the
    // receiver (approximate: no (1 - N.L) scaling of the normal inset).
    const float radius = unityKernelRadius(soft, quality);
    const PresetFacts facts = presetFacts(s);
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    b.constant = knobFloat(k, "m_ShadowDepthBias", 0.0, 10.0) * radius * facts.texel.front();
    b.constantUnit = BiasUnit::Metres;
    if (c.count > 1 && b.constant > 0.0f)
        for (float t : facts.texel) b.constantScale.push_back(t / facts.texel.front());
    b.slope = kUnityRasterSlopeBias;  // approximate: the raster bias takes the steeper map axis
    b.normalOffset = knobFloat(k, "m_ShadowNormalBias", 0.0, 10.0) * radius;
    b.normalOffsetUnit = OffsetUnit::Texels;
    return s;
}

namespace {

// Soft, quality from the filter; what URP cannot filter goes to lacks.
std::pair<bool, int> unitySoftOf(const FilterSettings& f, std::vector<std::string>& lacks) {
    if (f.kind == FilterKind::Pcf2x2) return {false, 2};
    if (f.kind == FilterKind::Tent) return {true, f.size <= 3 ? 1 : 2};
    lacks.push_back("filter '" + enumName(f.kind) + "': URP filters with one hardware tap or a tent (soft shadows)");
    return {f.kind != FilterKind::Hard, 2};
}

void unityCascadeKnobs(json& k, const Settings& s, const PresetFacts& f, std::vector<std::string>& lacks) {
    const CascadeSettings& c = s.cascades;
    const int n = std::min(c.count, 4);
    if (c.count > 4) lacks.push_back(std::to_string(c.count) + " cascades: URP has at most 4");
    k["m_ShadowCascadeCount"] = n;
    k["m_ShadowDistance"] = round6(f.end);
    const std::vector<double> fr = fractionsOfEnd(f);
    if (n == 2) k["m_Cascade2Split"] = fr.front();
    if (n >= 3) k[kUnitySplitKeys[n - 2]] = std::vector<double>(fr.begin(), fr.begin() + (n - 1));
    const int atlas = n == 1 ? c.mapSize : c.mapSize * 2;
    if (!isPowerOfTwo(atlas) || atlas < 256 || atlas > 8192)
        lacks.push_back("map size " + std::to_string(c.mapSize) + ": URP's atlas is 256 .. 8192 texels, a power of two");
    k["m_MainLightShadowmapResolution"] = std::clamp(atlas, 256, 8192);
    if (c.fit != FitMode::Sphere || !c.stabilize) lacks.push_back("fit '" + enumName(c.fit) + "': URP fits a snapped sphere per cascade");
    if (c.zExtension != ZExtension::SceneBounds) lacks.push_back("z extension '" + enumName(c.zExtension) + "': URP keeps every caster toward the light");
    if (n > 1 && c.selection != Selection::Map) lacks.push_back("cascade selection by view depth: URP picks the first sphere holding the pixel");
    if (c.blendBand > 0.0f) lacks.push_back("blending between cascades: URP has none");
    if (c.casterFaces != CasterFaces::Front) lacks.push_back("caster faces '" + enumName(c.casterFaces) + "': URP's casters cull as their materials (front faces)");
    k["m_CascadeBorder"] = fadeShareOfEnd(s, f);
}

void unityBiasKnobs(json& k, const Settings& s, const PresetFacts& f, float radius, std::vector<std::string>& lacks) {
    const BiasSettings& b = s.bias;
    if (b.constantUnit != BiasUnit::Metres) lacks.push_back("a bias in the box's depth: URP's is in texels of each cascade");
    // Within the inspector's 0 .. 10, so the knobs always load; beyond is listed.
    const double depth = std::max(0.0f, b.constant) / (radius * f.texel.front());
    if (depth > 10.0) lacks.push_back("a depth bias above 10 texels");
    k["m_ShadowDepthBias"] = round6(std::min(10.0, depth));
    if (b.constant < 0.0f) lacks.push_back("a bias away from the light");
    if (b.constant > 0.0f && !factorsFollowTexels(b.constantScale, f))
        lacks.push_back("a constant bias per cascade other than its texel: URP's bias is in each cascade's texels");
    if (std::abs(b.slope - kUnityRasterSlopeBias) > 0.01f) lacks.push_back("a slope bias other than URP's fixed raster bias 2.5");
    if (b.normalOffset / radius > 10.0f) lacks.push_back("a normal bias above 10 texels");
    if (b.normalOffsetUnit == OffsetUnit::Texels) k["m_ShadowNormalBias"] = round6(std::clamp(b.normalOffset / radius, 0.0f, 10.0f));
    else lacks.push_back("normal offset in metres: URP's normal bias is in texels");
    if (!b.slopeScale.empty() || !b.normalOffsetScale.empty()) lacks.push_back("slope or normal bias per cascade");
    if (b.receiverPlane) lacks.push_back("receiver-plane bias");
}

}  // namespace

EngineKnobs unityKnobsFor(const Settings& s) {
    EngineKnobs out{unityDefaults(), {}};
    const PresetFacts f = presetFacts(s);
    unityCascadeKnobs(out.knobs, s, f, out.lacks);
    const auto [soft, quality] = unitySoftOf(s.filter, out.lacks);
    out.knobs["m_SoftShadowsSupported"] = soft ? 1 : 0;
    out.knobs["m_SoftShadowQuality"] = quality;
    unityBiasKnobs(out.knobs, s, f, unityKernelRadius(soft, quality), out.lacks);
    return out;
}

const KnobTable& unityTable() {
    static const KnobTable table{
        unityDefaultKnobs, unityModel, unityKnobsFor, unitySnippets,
        {{"m_ShadowDistance", "m"}, {"m_Cascade2Split", "share of shadow distance"},
         {"m_Cascade3Split", "shares of shadow distance"}, {"m_Cascade4Split", "shares of shadow distance"},
         {"m_CascadeBorder", "share of shadow distance"}, {"m_MainLightShadowmapResolution", "texels"},
         {"m_ShadowDepthBias", "texels"}, {"m_ShadowNormalBias", "texels"}},
        // The UniversalRenderPipelineAsset's shadow fields.
        {"cascades.count", "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize", "cascades.fadeBand",
         "filter.kind", "filter.size", "bias.constant", "bias.normalOffset"}};
    return table;
}

}  // namespace st::xport
