// Babylon.js 9.28's CascadedShadowGenerator (@babylonjs/core Lights/Shadows), as knobs and as
// shadowtune settings. engines/babylon/NOTES.md cites the source line of each behaviour; the
// line numbers here are of cascadedShadowGenerator.pure.js (cSG) and shadowGenerator.js (SG).
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

// cSG:532-552 and SG:583-610; mapSize is the constructor's argument (1024 in Babylon's examples).
json babylonDefaults() {
    return {{"mapSize", 1024},          {"numCascades", 4},           {"lambda", 0.5},
            {"shadowMaxZ", nullptr},    {"stabilizeCascades", false}, {"depthClamp", true},
            {"cascadeBlendPercentage", 0.1}, {"bias", 0.00005},       {"normalBias", 0.0},
            {"filter", "PCF"},          {"filteringQuality", "high"}, {"darkness", 0.0}};
}

FilterSettings filterOf(const json& k) {
    FilterSettings f;
    const std::string filter = k.at("filter").get<std::string>();
    const std::string quality = k.at("filteringQuality").get<std::string>();
    if (quality != "low" && quality != "medium" && quality != "high")
        throw std::invalid_argument("settings.filteringQuality: '" + quality + "' is not low, medium or high");
    if (filter == "none") {
        f.kind = FilterKind::Hard;  // approximate: Babylon stores half-float depth for it (NOTES.md)
    } else if (filter == "PCF") {
        // SG:1370-1378: low one bilinear compare, medium PCF3 (4 taps), high PCF5 (9 taps).
        f.kind = quality == "low" ? FilterKind::Pcf2x2 : FilterKind::Tent;
        f.size = quality == "medium" ? 3 : 5;
    } else if (filter == "PCSS") {
        f.kind = FilterKind::Pcss;  // approximate: Babylon's blocker search and kernel differ
    } else {
        throw std::invalid_argument("settings.filter: '" + filter + "' is not PCF, PCSS or none");
    }
    return f;
}

}  // namespace

json babylonDefaultKnobs() { return babylonDefaults(); }

Settings babylonModel(const json& given, const Settings& view) {
    const json k = withDefaults(babylonDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = knobInt(k, "numCascades", 2, 4);
    c.scheme = SplitScheme::Practical;  // _splitFrustum (cSG:331-349): lambda between log and uniform
    c.lambda = knobFloat(k, "lambda", 0.0, 1.0);
    if (!k.at("shadowMaxZ").is_null()) {
        const float maxZ = knobFloat(k, "shadowMaxZ", 0.0, 1e9);
        if (maxZ > view.camera.nearPlane && maxZ < view.camera.farPlane) c.shadowDistance = maxZ;  // else ignored (cSG:169)
    }
    c.mapSize = knobInt(k, "mapSize", 256, 8192);
    // _computeCascadeFrustum (cSG:460-496): the slice's tight light-space box, or a sphere of radius
    // rounded up to 1/16 (approximate: Babylon centres it on the corners' mean); then the origin shift
    // (cSG:406-419) rounds the box's centre to whole texels, in both modes.
    c.fit = k.at("stabilizeCascades").get<bool>() ? FitMode::Sphere : FitMode::Cascade;
    c.sphereCentre = SphereCentre::CornersMean;  // cSG:473-483: around the corners' mean
    // cSG:423-459 finds the slice's corners through the float32 inverse of the camera's matrices.
    c.sliceCorners = SliceCorners::Float32Inverse;
    c.stabilize = true;
    c.snap = Snap::CentreRound;
    // cSG:371-405: with depthClamp the box starts at the slice and casters in front are clamped
    // (pancaking); without it the box reaches the casters' bounds toward the sun.
    const bool depthClamp = k.at("depthClamp").get<bool>();
    c.zExtension = depthClamp ? ZExtension::Pancake : ZExtension::SceneBounds;
    c.pancakeToCasters = depthClamp;
    c.selection = Selection::Interval;  // lightFragment.js:224-231: the first split at or beyond the depth
    c.blendBand = knobFloat(k, "cascadeBlendPercentage", 0.0, 0.5);
    c.casterFaces = CasterFaces::Front;  // SG:914-927: single-sided triangles cast only facing the sun
    s.filter = filterOf(k);
    if (knobFloat(k, "darkness", 0.0, 1.0) > 0.0f)
        throw std::invalid_argument("settings.darkness: shadowtune models darkness 0 only (a shadow's full strength)");
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    // shadowMapFragment.js: the caster's stored depth gains 1.5 x bias with depth clamp (the bias in
    // clip space and again in the fragment), 0.5 x without; receivers are not biased. For a constant
    // depth the two sides are the same comparison.
    (void)knobFloat(k, "bias", -1.0, 1.0);  // its range
    b.constant = static_cast<float>((depthClamp ? 1.5 : 0.5) * k.at("bias").get<double>());
    b.constantUnit = BiasUnit::Depth;
    b.slope = 0.0f;
    // shadowMapVertexNormalBias.js: casters move into their surface by normalBias x sin(N, L), metres.
    b.normalOffset = knobFloat(k, "normalBias", 0.0, 1e3);
    b.normalOffsetUnit = OffsetUnit::Metres;
    b.normalOffsetSide = NormalOffsetSide::CasterSin;
    return s;
}

EngineKnobs babylonKnobsFor(const Settings& s) {
    EngineKnobs out{babylonDefaults(), {}};
    json& k = out.knobs;
    const CascadeSettings& c = s.cascades;
    k["numCascades"] = std::clamp(c.count, 2, 4);
    if (c.count < 2 || c.count > 4) out.lacks.push_back(std::to_string(c.count) + " cascades: Babylon takes 2 to 4");
    if (c.scheme == SplitScheme::Practical) k["lambda"] = round6(c.lambda);
    else if (c.scheme == SplitScheme::Uniform) k["lambda"] = 0.0;
    else if (c.scheme == SplitScheme::Logarithmic) k["lambda"] = 1.0;
    else out.lacks.push_back("manual splits: Babylon splits by lambda");
    if (c.shadowDistance > 0.0f) k["shadowMaxZ"] = round6(c.shadowDistance);
    k["mapSize"] = c.mapSize;
    k["stabilizeCascades"] = c.fit == FitMode::Sphere;
    if (c.fit != FitMode::Sphere && c.fit != FitMode::Cascade)
        out.lacks.push_back("fit '" + enumName(c.fit) + "': Babylon fits the slice's box or a sphere");
    if (c.fit == FitMode::Sphere && c.sphereCentre != SphereCentre::CornersMean)
        out.lacks.push_back("the smallest sphere: Babylon centres its sphere on the slice corners' mean");
    if (!c.stabilize || c.snap != Snap::CentreRound) out.lacks.push_back("a box not centre-rounded to texels: Babylon always rounds");
    const bool depthClamp = c.zExtension == ZExtension::Pancake;
    k["depthClamp"] = depthClamp;
    if (depthClamp && !c.pancakeToCasters) out.lacks.push_back("a pancake over the whole slice: Babylon cuts it to the casters' bounds");
    if (c.zExtension == ZExtension::Distance || c.zExtension == ZExtension::None)
        out.lacks.push_back("z extension '" + enumName(c.zExtension) + "': Babylon pancakes or reaches the casters' bounds");
    k["cascadeBlendPercentage"] = round6(std::min(c.blendBand, 0.5f));  // the setter's range
    if (c.blendBand > 0.5f) out.lacks.push_back("a blend band above half a slice (cascadeBlendPercentage 0.5)");
    if (c.casterFaces != CasterFaces::Front) out.lacks.push_back("caster faces '" + enumName(c.casterFaces) + "': Babylon casts sun-facing faces");
    const double factor = depthClamp ? 1.5 : 0.5;
    if (s.bias.constantUnit == BiasUnit::Depth) k["bias"] = round6(double(s.bias.constant) / factor);
    else out.lacks.push_back("a constant bias in metres: Babylon's bias is a share of each box's depth");
    if (s.bias.normalOffsetUnit == OffsetUnit::Metres) k["normalBias"] = round6(s.bias.normalOffset);
    else if (s.bias.normalOffset > 0.0f) out.lacks.push_back("normal offset in texels: Babylon's normalBias is metres");
    if (s.bias.normalOffset > 0.0f && s.bias.normalOffsetSide != NormalOffsetSide::CasterSin)
        out.lacks.push_back("a normal offset on the receivers: Babylon moves the casters in, by normalBias x sin(N, L)");
    if (s.bias.slope > 0.0f) out.lacks.push_back("slope-scaled bias");
    if (s.bias.receiverPlane) out.lacks.push_back("receiver-plane bias");
    if (hasCascadeBias(s.bias)) out.lacks.push_back("bias per cascade");
    switch (s.filter.kind) {
        case FilterKind::Hard: k["filter"] = "none"; break;
        case FilterKind::Pcf2x2: k["filteringQuality"] = "low"; break;
        case FilterKind::Tent: k["filteringQuality"] = s.filter.size <= 3 ? "medium" : "high"; break;
        case FilterKind::Pcss: k["filter"] = "PCSS"; break;
        default: out.lacks.push_back("filter '" + enumName(s.filter.kind) + "': PCF high instead"); break;
    }
    return out;
}

const KnobTable& babylonTable() {
    static const KnobTable table{
        babylonDefaultKnobs, babylonModel, babylonKnobsFor, babylonSnippets,
        {{"mapSize", "texels"}, {"shadowMaxZ", "m"}, {"cascadeBlendPercentage", "share of a slice"},
         {"bias", "share of each box's depth"}, {"normalBias", "m"}},
        // CascadedShadowGenerator's properties.
        {"cascades.count", "cascades.lambda", "cascades.shadowDistance", "cascades.mapSize", "cascades.fit",
         "cascades.zExtension", "cascades.blendBand", "filter.kind", "filter.size", "bias.constant", "bias.normalOffset"}};
    return table;
}

}  // namespace st::xport
