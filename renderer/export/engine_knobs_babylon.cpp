// Babylon.js 9.28's CascadedShadowGenerator (@babylonjs/core Lights/Shadows), as knobs and as
// shadowtune settings. engines/babylon/NOTES.md cites the source lines of each behaviour.
#include "renderer/export/engine_knobs_detail.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

json babylonDefaults() {
    return {{"mapSize", 1024},          {"numCascades", 4},         {"lambda", 0.5},
            {"shadowMaxZ", nullptr},    {"stabilizeCascades", false}, {"depthClamp", true},
            {"cascadeBlendPercentage", 0.1}, {"bias", 0.00005},     {"normalBias", 0.0},
            {"filter", "PCF"},          {"filteringQuality", "high"}};
}

}  // namespace

json babylonDefaultKnobs() { return babylonDefaults(); }

Settings babylonModel(const json& given, const Settings& view) {
    const json k = withDefaults(babylonDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = knobInt(k, "numCascades", 2, 4);
    c.scheme = SplitScheme::Practical;
    c.lambda = knobFloat(k, "lambda", 0.0, 1.0);
    if (!k.at("shadowMaxZ").is_null()) c.shadowDistance = std::min(knobFloat(k, "shadowMaxZ", 1e-3, 1e9), view.camera.farPlane);
    c.mapSize = knobInt(k, "mapSize", 256, 8192);
    c.stabilize = k.at("stabilizeCascades").get<bool>();
    c.fit = c.stabilize ? FitMode::Sphere : FitMode::Cascade;
    c.zExtension = k.at("depthClamp").get<bool>() ? ZExtension::Pancake : ZExtension::None;
    c.blendBand = knobFloat(k, "cascadeBlendPercentage", 0.0, 0.5);
    c.casterFaces = CasterFaces::Both;
    FilterSettings& f = s.filter;
    f = FilterSettings{};
    const std::string filter = k.at("filter").get<std::string>();
    const std::string quality = k.at("filteringQuality").get<std::string>();
    if (filter == "none") {
        f.kind = FilterKind::Hard;
    } else if (filter == "PCF") {
        if (quality == "low") f.kind = FilterKind::Pcf2x2;
        else if (quality == "medium" || quality == "high") {
            f.kind = FilterKind::PcfNxN;
            f.size = quality == "medium" ? 3 : 5;
        } else throw std::invalid_argument("settings.filteringQuality: '" + quality + "' is not low, medium or high");
    } else {
        throw std::invalid_argument("settings.filter: '" + filter + "' is not PCF or none");
    }
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    b.constant = 0.0f;  // set from the cascade's depth range below (normalised depth units)
    b.slope = 0.0f;
    b.normalOffset = knobFloat(k, "normalBias", 0.0, 1e3);
    b.normalOffsetUnit = OffsetUnit::Metres;
    (void)knobFloat(k, "bias", -1.0, 1.0);
    return s;
}

EngineKnobs babylonKnobsFor(const Settings& s) {
    EngineKnobs out{babylonDefaults(), {}};
    json& k = out.knobs;
    const CascadeSettings& c = s.cascades;
    k["numCascades"] = std::clamp(c.count, 2, 4);
    if (c.count < 2 || c.count > 4) out.lacks.push_back(std::to_string(c.count) + " cascades: Babylon takes 2 to 4");
    if (c.scheme == SplitScheme::Practical) k["lambda"] = c.lambda;
    else out.lacks.push_back("split scheme '" + enumName(c.scheme) + "': Babylon splits by lambda");
    if (c.shadowDistance > 0.0f) k["shadowMaxZ"] = c.shadowDistance;
    k["mapSize"] = c.mapSize;
    k["stabilizeCascades"] = c.fit == FitMode::Sphere;
    k["depthClamp"] = c.zExtension == ZExtension::Pancake;
    k["cascadeBlendPercentage"] = c.blendBand;
    if (s.bias.normalOffsetUnit == OffsetUnit::Metres) k["normalBias"] = s.bias.normalOffset;
    else if (s.bias.normalOffset > 0.0f) out.lacks.push_back("normal offset in texels: Babylon's normalBias is metres");
    if (s.bias.slope > 0.0f) out.lacks.push_back("slope-scaled bias");
    if (s.bias.receiverPlane) out.lacks.push_back("receiver-plane bias");
    switch (s.filter.kind) {
        case FilterKind::Hard: k["filter"] = "none"; break;
        case FilterKind::Pcf2x2: k["filteringQuality"] = "low"; break;
        case FilterKind::PcfNxN: k["filteringQuality"] = s.filter.size <= 3 ? "medium" : "high"; break;
        default: out.lacks.push_back("filter '" + enumName(s.filter.kind) + "': PCF high instead"); break;
    }
    return out;
}

}  // namespace st::xport
