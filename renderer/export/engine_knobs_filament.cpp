// Filament's directional shadows (LightManager::ShadowOptions and View::setShadowType), as knobs and
// as shadowtune settings. Read from google/filament v1.51.0 at 2763931b (docs/engines.md "Filament"
// has the table of lines): filament/include/filament/LightManager.h:208-350 (the field initialisers),
// filament/src/ShadowMapManager.cpp (splits :530-533 and :1041-1047, normal bias :673-675, DEPTH16
// :1001), filament/src/ShadowMap.cpp (stable :162-193 and :614-639, constant bias :234-238),
// shaders/src/shadowing.fs (ShadowSample_PCF_Low), shaders/src/common_shadowing.glsl:14-24 (normal
// offset), shaders/src/light_directional.fs:61-66 with filament/src/PerViewUniforms.cpp:295-298 (fade).
// Filament does not run here: this model is a reading of the source, never measured against it.
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"
#include "renderer/settings/number_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

constexpr int kFilamentCascadeLimit = 4;  // CONFIG_MAX_SHADOW_CASCADES (EngineEnums.h:99)
constexpr std::array<double, 3> kFilamentSplitDefaults{0.125, 0.25, 0.5};
// light_directional.fs: saturate(5 - 5 z^2 / shadowFar^2) reaches 1 at z = sqrt(0.8) shadowFar.
const double kFilamentFadeStart = std::sqrt(0.8);

// ShadowOptions' field initialisers (LightManager.h:208-350) and View's default shadow type PCF.
// The keys are the C++ field names the snippet writes; shadowType is View::setShadowType's.
json filamentDefaults() {
    return {{"mapSize", 1024},
            {"shadowCascades", 1},
            {"cascadeSplitPositions", {0.125, 0.25, 0.5}},
            {"constantBias", 0.001},
            {"normalBias", 1.0},
            {"shadowFar", 0.0},
            {"shadowNearHint", 1.0},
            {"shadowFarHint", 100.0},
            {"stable", false},
            {"lispsm", true},
            {"polygonOffsetConstant", 0.5},
            {"polygonOffsetSlope", 2.0},
            {"shadowType", "PCF"}};
}

// The split depths: near + (far - near) x position, far = shadowFar when > 0 (ShadowMapManager.cpp
// :530-533, :1041-1047), here capped at the camera's far plane, where shadowtune's cascades end.
std::vector<float> filamentSplits(const json& k, const Settings& view, int count, float end) {
    const json& p = k.at("cascadeSplitPositions");
    if (!p.is_array() || p.size() != kFilamentSplitDefaults.size())
        throw std::invalid_argument("settings.cascadeSplitPositions: 3 positions in (0, 1), got " + p.dump());
    std::vector<float> out;
    double previous = 0.0;
    for (int i = 0; i + 1 < count; ++i) {  // the positions past count - 1 are unused
        const json& v = p[std::size_t(i)];
        if (!v.is_number() || v.get<double>() <= previous || v.get<double>() >= 1.0)
            throw std::invalid_argument("settings.cascadeSplitPositions[" + std::to_string(i) + "]: " + v.dump() +
                                        " must lie above the position before it and below 1");
        previous = v.get<double>();
        out.push_back(float(view.camera.nearPlane + previous * (end - view.camera.nearPlane)));
    }
    return out;
}

// The share of the last cascade the far fade covers: from sqrt(0.8) shadowFar to shadowFar, when
// shadowFar ends the shadows before the far plane (approximate: linear here, in z^2 in Filament).
float filamentFadeBand(float shadowFar, const std::vector<float>& manualSplits, const Settings& view) {
    if (!(shadowFar > 0.0f) || shadowFar >= view.camera.farPlane) return 0.0f;
    const double lastStart = manualSplits.empty() ? view.camera.nearPlane : manualSplits.back();
    return float(std::min(1.0, round6((1.0 - kFilamentFadeStart) * shadowFar / (shadowFar - lastStart))));
}

void filamentFilter(FilterSettings& f, const std::string& type) {
    f = FilterSettings{};
    if (type == "PCF") {
        // ShadowSample_PCF_Low (shaders/src/shadowing.fs): Castano's 4 bilinear taps over 3 x 3
        // texels, the weights and offsets of shadowtune's tent of 3.
        f.kind = FilterKind::Tent;
        f.size = 3;
    } else if (type == "VSM") {
        // Approximate: Filament's VSM warps depth by exp(vsmExponent x depth) (EVSM, positive warp);
        // its blur, exponent and light-bleed cut are VsmShadowOptions', shadowtune's defaults here.
        f.kind = FilterKind::Evsm2;
    } else if (type == "PCSS") {
        f.kind = FilterKind::Pcss;  // approximate: Filament sizes the penumbra by SoftShadowOptions
    } else {
        throw std::invalid_argument("settings.shadowType: '" + type + "' is not PCF, VSM or PCSS (DPCF is not modelled)");
    }
}

}  // namespace

json filamentDefaultKnobs() { return filamentDefaults(); }

Settings filamentModel(const json& given, const Settings& view) {
    const json k = withDefaults(filamentDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = knobInt(k, "shadowCascades", 1, kFilamentCascadeLimit);
    const float shadowFar = knobFloat(k, "shadowFar", 0.0, 1e7);
    const float end = shadowFar > 0.0f ? std::min(shadowFar, view.camera.farPlane) : view.camera.farPlane;
    c.shadowDistance = shadowFar > 0.0f && shadowFar < view.camera.farPlane ? shadowFar : 0.0f;
    c.scheme = c.count > 1 ? SplitScheme::Manual : SplitScheme::Uniform;  // one cascade: no split
    c.manualSplits = filamentSplits(k, view, c.count, end);
    c.mapSize = knobInt(k, "mapSize", 256, 8192);
    if ((c.mapSize & (c.mapSize - 1)) != 0)
        throw std::invalid_argument("settings.mapSize: " + std::to_string(c.mapSize) + " is not a power of two (LightManager.h)");
    // stable (ShadowMap.cpp): a snapped sphere around the slice, LiSPSM and the focus on casters off.
    // Not stable: the light frustum fitted to the slice, focused on the casters and receivers; the
    // depth reaches the casters either way. Approximate: shadowtune's cascade fit is the slice's box
    // alone, and with shadowFar > 0 Filament's stable sphere is centred on the camera, radius shadowFar.
    const bool stable = k.at("stable").get<bool>();
    c.fit = stable ? FitMode::Sphere : FitMode::Cascade;
    c.stabilize = stable;
    c.zExtension = ZExtension::SceneBounds;
    c.selection = Selection::Interval;  // getters.fs:128-133: by view depth
    c.fadeBand = filamentFadeBand(shadowFar, c.manualSplits, view);
    // Materials cull back faces by default and the shadow pass takes the instance's shadow culling
    // mode (RenderPass.cpp generateCommandsImpl, MaterialInstance::setCullingMode sets both).
    c.casterFaces = CasterFaces::Front;
    // lispsm (default true) warps the single cascade's projection; shadowtune does not, so the
    // model renders it unwarped (knobsFor writes false, so the pasted text renders what was
    // modelled). shadowNearHint / shadowFarHint only tune LiSPSM: range-checked, not modelled.
    (void)k.at("lispsm").get<bool>();
    const float nearHint = knobFloat(k, "shadowNearHint", 0.0, 1e7);
    (void)knobFloat(k, "shadowFarHint", nearHint, 1e7);
    filamentFilter(s.filter, k.at("shadowType").get<std::string>());
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    // ShadowMap.cpp:234-238 moves the light camera constantBias metres away: as the receiver toward it.
    b.constant = knobFloat(k, "constantBias", -10.0, 10.0);
    b.constantUnit = BiasUnit::Metres;
    // polygonOffsetSlope: a glPolygonOffset factor, depth slope per texel ~ texel x tan: shadowtune's
    // slope unit (approximate: the hardware takes the steeper map axis). polygonOffsetConstant counts
    // steps of the 16-bit PCF maps (DEPTH16), which shadowtune's 32-bit float maps do not have.
    b.slope = knobFloat(k, "polygonOffsetSlope", 0.0, 100.0);
    (void)knobFloat(k, "polygonOffsetConstant", 0.0, 100.0);
    // normalBias x half a texel (ShadowMapManager.cpp:673-675) along the normal x sin of the angle
    // to the light (common_shadowing.glsl:14-24); shadowtune moves it at every angle (approximate).
    b.normalOffset = 0.5f * knobFloat(k, "normalBias", 0.0, 100.0);
    b.normalOffsetUnit = OffsetUnit::Texels;
    return s;
}

EngineKnobs filamentKnobsFor(const Settings& s) {
    EngineKnobs out{filamentDefaults(), {}};
    json& k = out.knobs;
    std::vector<std::string>& lacks = out.lacks;
    const CascadeSettings& c = s.cascades;
    const std::vector<float> splits = presetSplits(s);
    const int used = std::min(c.count, kFilamentCascadeLimit);
    if (c.count > kFilamentCascadeLimit) lacks.push_back(std::to_string(c.count) + " cascades: Filament takes 1 to 4");
    k["shadowCascades"] = used;
    const double near = splits.front(), end = splits.back();
    json positions = json::array();
    double previous = 0.0;
    for (std::size_t i = 0; i < kFilamentSplitDefaults.size(); ++i) {
        // The unused positions keep Filament's defaults, or lie halfway to 1 past the used ones.
        double p = kFilamentSplitDefaults[i] > previous ? kFilamentSplitDefaults[i] : round6(0.5 * (previous + 1.0));
        if (int(i) + 1 < used) p = round6((double(splits[i + 1]) - near) / (end - near));
        positions.push_back(p);
        previous = p;
    }
    k["cascadeSplitPositions"] = positions;
    k["shadowFar"] = c.shadowDistance > 0.0f ? tidyFloat(c.shadowDistance) : 0.0;
    if (c.depthBounds != DepthBounds::Off) lacks.push_back("depth-bounds fit: Filament splits its fixed range");
    k["mapSize"] = c.mapSize;
    if (!c.mapSizes.empty()) lacks.push_back("a map size per cascade: Filament's mapSize is one");
    const bool stable = c.fit == FitMode::Sphere;
    k["stable"] = stable;
    if ((c.fit != FitMode::Sphere && c.fit != FitMode::Cascade) || c.stabilize != stable)
        lacks.push_back("fit '" + enumName(c.fit) + (c.stabilize ? "', snapped" : "', unsnapped") +
                        ": Filament fits the slice unsnapped, or a snapped sphere (stable)");
    k["lispsm"] = false;  // shadowtune does not warp: what Filament then renders is what was modelled
    if (c.zExtension != ZExtension::SceneBounds) lacks.push_back("z extension '" + enumName(c.zExtension) + "': Filament's light frustum reaches the casters");
    if (c.selection != Selection::Interval) lacks.push_back("map-based cascade selection: Filament picks by view depth");
    if (c.casterFaces != CasterFaces::Front) lacks.push_back("caster faces '" + enumName(c.casterFaces) + "': Filament's materials cull back faces");
    if (c.blendBand > 0.0f) lacks.push_back("blending between cascades: Filament switches at the split");
    std::vector<float> manual(splits.begin() + 1, splits.end() - 1);
    const float fade = filamentFadeBand(c.shadowDistance, manual, s);
    if (std::abs(c.fadeBand - fade) > 1e-4f)
        lacks.push_back("a far fade of " + formatFloat(c.fadeBand) + ": Filament fades from 0.894 x shadowFar when shadowFar ends the shadows (" +
                        formatFloat(fade) + " here)");
    const FilterSettings& f = s.filter;
    if (f.kind == FilterKind::Tent && f.size == 3) k["shadowType"] = "PCF";
    else if (f.kind == FilterKind::Evsm2) k["shadowType"] = "VSM";
    else if (f.kind == FilterKind::Pcss) k["shadowType"] = "PCSS";
    else lacks.push_back("filter '" + enumName(f.kind) + "': Filament's PCF is a tent of 3 (VSM, PCSS otherwise)");
    if (f.contact != ContactShadows::Off || f.screenSpace != ScreenSpace::Off)
        lacks.push_back("contact shadows or screen-space blur: not in Filament's knob table");
    const BiasSettings& b = s.bias;
    if (b.constantUnit == BiasUnit::Metres) k["constantBias"] = round6(b.constant);
    else lacks.push_back("a bias in the box's depth: Filament's constantBias is metres");
    k["polygonOffsetSlope"] = round6(b.slope);
    if (b.normalOffsetUnit == OffsetUnit::Texels) k["normalBias"] = round6(2.0 * b.normalOffset);
    else lacks.push_back("normal offset in metres: Filament's normalBias is half texels");
    if (b.receiverPlane) lacks.push_back("receiver-plane bias");
    if (hasCascadeBias(b)) lacks.push_back("bias per cascade");
    return out;
}

const KnobTable& filamentTable() {
    static const KnobTable table{
        filamentDefaultKnobs, filamentModel, filamentKnobsFor, filamentSnippets,
        {{"mapSize", "texels"}, {"cascadeSplitPositions", "share of shadowFar - near"}, {"constantBias", "m"},
         {"normalBias", "half texels"}, {"shadowFar", "m"}, {"shadowNearHint", "m"}, {"shadowFarHint", "m"},
         {"polygonOffsetConstant", "16-bit depth steps"}, {"polygonOffsetSlope", "x depth slope per texel"}},
        // ShadowOptions and View::setShadowType.
        {"cascades.count", "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize", "cascades.fit",
         "cascades.stabilize", "cascades.fadeBand", "filter.kind", "bias.constant", "bias.slope", "bias.normalOffset"}};
    return table;
}

}  // namespace st::xport
