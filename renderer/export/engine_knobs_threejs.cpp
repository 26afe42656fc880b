// three.js r187's CSM addon (examples/jsm/csm/CSM.js) and WebGLRenderer shadows, as knobs and as
// shadowtune settings. Line numbers are of node_modules/three 0.187.0 (engines/package-lock.json).
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

// CSM.js constructor (lines 36-72): `data.x || default`, so 0 and false also take the default.
json threejsDefaults() {
    return {{"cascades", 3},        {"mode", "practical"},   {"breaks", nullptr},       {"maxFar", 100000.0},
            {"shadowMapSize", 2048}, {"shadowBias", 0.000001}, {"normalBias", 0.0},     {"radius", 1.0},
            {"lightNear", 1.0},      {"lightFar", 2000.0},     {"lightMargin", 200.0},  {"fade", false},
            {"shadowMapType", "PCFShadowMap"}, {"shadowSide", nullptr}};
}

SplitScheme schemeOf(const std::string& mode) {
    if (mode == "practical") return SplitScheme::Practical;
    if (mode == "uniform") return SplitScheme::Uniform;
    if (mode == "logarithmic") return SplitScheme::Logarithmic;
    if (mode == "custom") return SplitScheme::Manual;
    throw std::invalid_argument("settings.mode: '" + mode + "' is not practical, uniform, logarithmic or custom");
}

CasterFaces facesOf(const json& side) {
    if (side.is_null()) return CasterFaces::Back;  // WebGLShadowMap.js:51, 490: FrontSide -> BackSide
    const std::string s = side.get<std::string>();
    if (s == "back") return CasterFaces::Back;
    if (s == "front") return CasterFaces::Front;
    if (s == "double") return CasterFaces::Both;
    throw std::invalid_argument("settings.shadowSide: '" + s + "' is not null, front, back or double");
}

}  // namespace

json threejsDefaultKnobs() { return threejsDefaults(); }

// CSM.js reads its numbers as `data.x || default`: 0 (and null) take the default, as in three.js.
json orDefaults(json k) {
    const json d = threejsDefaults();
    for (const char* name : {"cascades", "maxFar", "shadowMapSize", "shadowBias", "lightNear", "lightFar", "lightMargin"})
        if (k.at(name).is_null() || (k.at(name).is_number() && k.at(name).get<double>() == 0.0)) k[name] = d.at(name);
    return k;
}

Settings threejsModel(const json& given, const Settings& view) {
    const json k = orDefaults(withDefaults(threejsDefaults(), given));
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = knobInt(k, "cascades", 1, kMaxCascades);
    c.scheme = schemeOf(k.at("mode").get<std::string>());
    c.lambda = 0.5f;  // CSM.js:177 practicalSplit( ..., 0.5, ... )
    // CSMFrustum.js: the far corners are pulled in to maxFar; breaks are fractions of that far.
    const float far = std::min(view.camera.farPlane, knobFloat(k, "maxFar", 1e-3, 1e9));
    c.shadowDistance = far < view.camera.farPlane ? far : 0.0f;
    if (c.scheme == SplitScheme::Manual) {
        const json& breaks = k.at("breaks");
        if (!breaks.is_array() || int(breaks.size()) < c.count - 1)
            throw std::invalid_argument("settings.breaks: custom mode needs " + std::to_string(c.count - 1) +
                                        " fractions of the far distance before the final 1");
        for (int i = 0; i + 1 < c.count; ++i) c.manualSplits.push_back(breaks[std::size_t(i)].get<float>() * far);
    }
    c.mapSize = knobInt(k, "shadowMapSize", 256, 8192);
    // CSM.js _updateShadowBounds (113-158) and update() (221-268): the diagonal square, its
    // centre floored to texels, the light lightMargin beyond the slice's sun side, looking
    // lightNear..lightFar from there.
    c.fit = FitMode::Diagonal;
    c.stabilize = true;
    c.snap = Snap::CentreFloor;
    const float lightNear = knobFloat(k, "lightNear", 0.0, 1e7);
    const float lightFar = knobFloat(k, "lightFar", lightNear + 1e-3, 1e7);
    c.zExtension = ZExtension::Distance;
    c.zExtensionDistance = std::max(0.0f, knobFloat(k, "lightMargin", 0.0, 1e7) - lightNear);
    c.lightDepth = lightFar - lightNear;
    c.selection = Selection::Interval;  // CSMShader.js:250: linearDepth in [breaks i-1, breaks i)
    c.casterFaces = facesOf(k.at("shadowSide"));
    const std::string type = k.at("shadowMapType").get<std::string>();
    FilterSettings& f = s.filter;
    f = FilterSettings{};
    if (type == "PCFShadowMap" || type == "PCFSoftShadowMap") {  // PCFSoft is PCF since r182 (WebGLShadowMap.js:99)
        f.kind = FilterKind::Vogel;  // shadowmap_pars_fragment.glsl.js:160-190
        f.vogelTaps = 5;
        f.radius = knobFloat(k, "radius", 0.0, 32.0);
    } else if (type == "BasicShadowMap") {
        f.kind = FilterKind::Hard;
    } else if (type == "VSMShadowMap") {
        // shadowmap_pars_fragment.glsl.js:239: the variance floored at 1e-7.
        f.kind = FilterKind::Vsm;
        f.minVariance = 1e-7f;
        f.bleedLow = 0.3f, f.bleedHigh = 0.95f;  // line 248: (p_max - 0.3) / 0.65
        // vsm.glsl.js: 8 taps over +-radius texels in each direction (WebGLShadowMap.js VSMPass);
        // approximate: shadowtune's Gaussian over round(radius) texels each side.
        f.blurRadius = int(std::lround(std::clamp(knobFloat(k, "radius", 0.0, 32.0), 0.0f, 16.0f)));
        // WebGLShadowMap.js:484-486: for VSM a material casts its own side, not the flipped one.
        if (k.at("shadowSide").is_null()) c.casterFaces = CasterFaces::Front;
    } else {
        throw std::invalid_argument("settings.shadowMapType: '" + type + "' is not PCFShadowMap, BasicShadowMap or VSMShadowMap");
    }
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    // shadowCoord.z += shadowBias (shadowmap_pars_fragment.glsl.js:158): positive moves the
    // receiver away from the light, in depth normalised over lightNear..lightFar.
    b.constant = -knobFloat(k, "shadowBias", -1.0, 1.0) * c.lightDepth;
    b.slope = 0.0f;
    b.normalOffset = knobFloat(k, "normalBias", 0.0, 1e3);  // world units (shadowmap_vertex.glsl.js:38)
    b.normalOffsetUnit = OffsetUnit::Metres;
    if (k.at("fade").get<bool>()) c.blendBand = 0.1f;  // approximate: CSMShader.js's margin grows with depth
    return s;
}

EngineKnobs threejsKnobsFor(const Settings& s) {
    EngineKnobs out{threejsDefaults(), {}};
    json& k = out.knobs;
    const CascadeSettings& c = s.cascades;
    k["cascades"] = c.count;
    const float far = c.shadowDistance > 0.0f ? std::min(c.shadowDistance, s.camera.farPlane) : s.camera.farPlane;
    if (c.shadowDistance > 0.0f) k["maxFar"] = round6(far);
    switch (c.scheme) {
        case SplitScheme::Uniform: k["mode"] = "uniform"; break;
        case SplitScheme::Logarithmic: k["mode"] = "logarithmic"; break;
        case SplitScheme::Practical:
            if (c.lambda == 0.5f) {
                k["mode"] = "practical";
                break;
            }
            [[fallthrough]];  // another lambda: its splits, as custom breaks
        case SplitScheme::Manual: {
            k["mode"] = "custom";
            json breaks = json::array();
            const std::vector<float> splits = presetSplits(s);
            for (std::size_t i = 1; i + 1 < splits.size(); ++i) breaks.push_back(round6(double(splits[i]) / double(far)));
            breaks.push_back(1.0);
            k["breaks"] = breaks;
        }
    }
    k["shadowMapSize"] = c.mapSize;
    const double lightNear = 1.0;
    const double lightDepth = c.lightDepth > 0.0f ? round6(c.lightDepth) : 1999.0;
    k["lightNear"] = lightNear;
    k["lightFar"] = round6(lightNear + lightDepth);
    if (c.zExtension == ZExtension::Distance) k["lightMargin"] = round6(c.zExtensionDistance + lightNear);
    else out.lacks.push_back("z extension '" + enumName(c.zExtension) + "': three.js reaches lightMargin toward the sun");
    k["shadowBias"] = round6(-double(s.bias.constant) / lightDepth) + 0.0;  // + 0.0: no "-0"
    if (s.bias.normalOffsetUnit == OffsetUnit::Metres) k["normalBias"] = round6(s.bias.normalOffset);
    else if (s.bias.normalOffset > 0.0f) out.lacks.push_back("normal offset in texels: three.js's normalBias is metres");
    if (s.bias.slope > 0.0f) out.lacks.push_back("slope-scaled bias");
    if (s.bias.receiverPlane) out.lacks.push_back("receiver-plane bias");
    if (hasCascadeBias(s.bias)) out.lacks.push_back("bias per cascade");
    if (c.fit != FitMode::Diagonal) out.lacks.push_back("fit '" + enumName(c.fit) + "': three.js fits the diagonal square");
    if (!c.stabilize || c.snap != Snap::CentreFloor) out.lacks.push_back("a box not centre-floored to texels: three.js always floors the centre");
    if (c.selection != Selection::Interval) out.lacks.push_back("map-based cascade selection");
    if (c.blendBand > 0.0f) k["fade"] = true;
    k["shadowSide"] = c.casterFaces == CasterFaces::Back ? json(nullptr)
                      : c.casterFaces == CasterFaces::Front ? json("front")
                                                            : json("double");
    switch (s.filter.kind) {
        case FilterKind::Hard: k["shadowMapType"] = "BasicShadowMap"; break;
        case FilterKind::Pcf2x2: k["radius"] = 0.0; break;  // five taps at one point: the 2x2 compare
        case FilterKind::Vogel:
            k["radius"] = round6(s.filter.radius);
            if (s.filter.vogelTaps != 5) out.lacks.push_back("Vogel taps other than 5");
            break;
        case FilterKind::Vsm:
            k["shadowMapType"] = "VSMShadowMap";
            k["radius"] = s.filter.blurRadius;  // its blur's reach, texels each side
            if (s.filter.bleedLow != 0.3f || s.filter.bleedHigh != 0.95f)
                out.lacks.push_back("a bleed remap other than three.js's (p - 0.3) / 0.65");
            break;
        default: out.lacks.push_back("filter '" + enumName(s.filter.kind) + "': PCF with radius 1 instead"); break;
    }
    return out;
}

const KnobTable& threejsTable() {
    static const KnobTable table{
        threejsDefaultKnobs, threejsModel, threejsKnobsFor, threejsSnippets,
        {{"maxFar", "m"}, {"shadowMapSize", "texels"}, {"shadowBias", "share of lightNear..lightFar"},
         {"normalBias", "m"}, {"radius", "texels"}, {"lightNear", "m"}, {"lightFar", "m"}, {"lightMargin", "m"},
         {"breaks", "shares of maxFar"}},
        // CSM's options, the lights' shadow properties, the renderer's map type, shadowSide.
        {"cascades.count", "cascades.scheme", "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize",
         "cascades.zExtensionDistance", "cascades.lightDepth", "cascades.casterFaces", "cascades.blendBand", "filter.kind",
         "filter.radius", "bias.constant", "bias.normalOffset"}};
    return table;
}

}  // namespace st::xport
