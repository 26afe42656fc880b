#include "renderer/export/export_common.h"

#include "renderer/csm/cascade_plan.h"
#include "renderer/settings/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace st::xport {

void addLacks(EngineExport& e, const std::vector<std::string>& lacks) {
    for (const std::string& lack : lacks) e.add("(" + lack.substr(0, lack.find(':')) + ")", nullptr, Mapping::NoEquivalent, lack);
}

PresetFacts presetFacts(const Settings& s) {
    Settings flat = s;
    flat.cascades.zExtension = ZExtension::None;  // x,y texel size is independent of z
    const float aspect = float(s.output.width) / float(s.output.height);
    const csm::CascadePlan plan = csm::planCascades(flat, aspect, csm::Aabb{});
    PresetFacts f;
    f.splits = plan.splits;
    f.nearPlane = s.camera.nearPlane;
    f.end = plan.splits.back();
    for (const csm::CascadeFit& c : plan.cascades) f.texel.push_back(c.texelWorldSize);
    return f;
}

std::vector<double> fractionsOfRange(const PresetFacts& f) {
    std::vector<double> out;
    for (size_t i = 1; i + 1 < f.splits.size(); ++i)
        out.push_back(round6((double(f.splits[i]) - f.nearPlane) / (double(f.end) - f.nearPlane)));
    return out;
}

std::vector<double> fractionsOfEnd(const PresetFacts& f) {
    std::vector<double> out;
    for (size_t i = 1; i + 1 < f.splits.size(); ++i) out.push_back(round6(double(f.splits[i]) / f.end));
    return out;
}

double round6(double v) {
    if (v == 0.0 || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, 5 - std::floor(std::log10(std::fabs(v))));
    return std::round(v * scale) / scale;
}

nlohmann::json numbers(const std::vector<double>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (double x : v) a.push_back(x);
    return a;
}

std::string texelNote(const PresetFacts& f) {
    return formatNumber(round6(f.texel.front())) + " m (cascade 0 as shadowtune fits it in this preset)";
}

double fadeShareOfEnd(const Settings& s, const PresetFacts& f) {
    if (s.cascades.fadeBand <= 0.0f || f.end <= 0.0f || f.splits.size() < 2) return 0.0;
    const double lastStart = f.splits[f.splits.size() - 2];
    return round6(double(s.cascades.fadeBand) * (double(f.end) - lastStart) / double(f.end));
}

std::string filterKindText(const Settings& s) {
    return "filter.kind " + std::string(EnumNames<FilterKind>::names[size_t(s.filter.kind)]);
}

bool factorsFollowTexels(const std::vector<float>& factors, const PresetFacts& f) {
    for (std::size_t i = 0; i < f.texel.size(); ++i)
        if (std::abs(cascadeFactor(factors, int(i)) - f.texel[i] / f.texel.front()) > 0.01f) return false;
    return true;
}

namespace {
// bias.constantScale / slopeScale / normalOffsetScale: no engine's light or project settings hold a
// bias per cascade (Godot's shadow_bias grows with each split's depth range by itself, and
// godotengine/godot #100375 asks for more), so each scaled bias is listed with its values per cascade.
// Unity URP and Unreal count their depth bias in texels of each cascade: factors equal to the
// cascades' texel ratios are what they do anyway.
bool followsTexels(Engine engine, const Settings& s, const std::vector<float>& factors) {
    return (engine == Engine::Unity || engine == Engine::Unreal) && factorsFollowTexels(factors, presetFacts(s));
}

void addCascadeBias(EngineExport& e, const Settings& s) {
    const BiasSettings& b = s.bias;
    if (!hasCascadeBias(b)) return;
    struct Scaled {
        const char* name;
        const char* path;
        float global;
        float (*of)(const CascadeBias&);
    };
    const Scaled scaled[] = {
        {"(constant bias per cascade)", "bias.constantScale", b.constant, [](const CascadeBias& c) { return c.constant; }},
        {"(slope bias per cascade)", "bias.slopeScale", b.slope, [](const CascadeBias& c) { return c.slope; }},
        {"(normal offset per cascade)", "bias.normalOffsetScale", b.normalOffset,
         [](const CascadeBias& c) { return c.normalOffset; }}};
    for (const Scaled& k : scaled) {
        const FieldValue factors = findField(k.path)->get(s);
        const auto& list = std::get<std::vector<float>>(factors);
        const bool varies = std::any_of(list.begin(), list.end(), [](float v) { return v != 1.0f; });
        if (!varies || !fieldApplies(s, k.path)) continue;
        if (k.path == std::string_view("bias.constantScale") && followsTexels(e.engine, s, list)) {
            std::vector<double> rounded;
            for (float v : list) rounded.push_back(round6(v));
            e.add(k.name, numbers(rounded), Mapping::Exact,
                  "bias.constantScale follows each cascade's texel, as this engine's bias does by itself (it counts in "
                  "texels of each cascade: engine_knobs_unity.cpp, engine_knobs_unreal.cpp)");
            continue;
        }
        std::vector<double> values;
        for (int i = 0; i < s.cascades.count; ++i) values.push_back(round6(k.of(cascadeBias(b, i))));
        e.add(k.name, numbers(values), Mapping::NoEquivalent,
              std::string(k.path) + ": the engine applies one value to every cascade; the global " +
                  formatNumber(round6(k.global)) + " exported above");
    }
}
}  // namespace

void addShadowtuneOnly(EngineExport& e, const Settings& s, bool engineFades) {
    const CascadeSettings& c = s.cascades;
    using M = Mapping;
    if (c.depthBounds != DepthBounds::Off || c.fit == FitMode::Samples)
        e.add("(depth-fitted cascades)", true, M::NoEquivalent,
              "cascades.depthBounds / fit 'samples' fit the splits (and boxes) to the depth the camera sees each frame "
              "(SDSM); the engine places its splits from the settings alone");
    const bool mixedSizes = std::any_of(c.mapSizes.begin(), c.mapSizes.end(), [&](int v) { return v != c.mapSize; });
    if (mixedSizes)
        e.add("(map size per cascade)", numbers(std::vector<double>(c.mapSizes.begin(), c.mapSizes.end())), M::NoEquivalent,
              "cascades.mapSizes: the engine gives every cascade one size; mapSize exported above");
    const bool skips = std::any_of(c.updateInterval.begin(), c.updateInterval.end(), [](float v) { return v > 1.0f; });
    if (skips)
        e.add("(cascade update interval)", numbers(std::vector<double>(c.updateInterval.begin(), c.updateInterval.end())),
              M::NoEquivalent, "cascades.updateInterval: frames between redraws of each cascade; no settings field for it");
    if (s.filter.screenSpace != ScreenSpace::Off)
        e.add("(screen-space shadow blur)", true, M::NoEquivalent,
              "filter.screenSpace: the shadow mask blurred in screen space (seed 001); no shadow setting does it");
    if (s.filter.padding)
        e.add("(PCF padding)", true, M::NoEquivalent, "filter.padding grows each light box by the kernel's reach (seed 004)");
    addCascadeBias(e, s);
    if (c.matricesOneFrameLate)
        e.add("(matrices one frame late)", true, M::NoEquivalent,
              "cascades.matricesOneFrameLate: a debug reproduction of three.js #30053 (the maps sampled through the "
              "previous frame's light matrices, so shadows flicker); engines sample the current frame's: leave it off");
    if (!engineFades && c.fadeBand > 0.0f)
        e.add("(far fade)", round6(c.fadeBand), M::NoEquivalent,
              "cascades.fadeBand fades the last cascade's far end to lit; the engine cuts shadows off at the distance");
}

void addKnobsWithoutSetting(EngineExport& e, const Settings& s, const KnobAnswers& a) {
    const CascadeSettings& c = s.cascades;
    if (c.cameraRelative && !a.cameraRelative.empty())
        e.add("(camera-relative light space)", true, Mapping::NoEquivalent, "cascades.cameraRelative: " + a.cameraRelative);
    if (c.fitFovY > 0.0f && !a.fitFovY.empty())
        e.add("(fit field of view)", round6(c.fitFovY), Mapping::NoEquivalent, "cascades.fitFovY: " + a.fitFovY);
    if (s.filter.contact != ContactShadows::Off && !a.contact.empty())
        e.add("(contact shadows)", round6(s.filter.contactLength), Mapping::NoEquivalent,
              "filter.contact, a screen-space march of filter.contactLength m toward the sun: " + a.contact);
}

}  // namespace st::xport
