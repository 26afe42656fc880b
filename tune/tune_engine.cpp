#include "tune/tune_engine.h"

#include "tune/tune_engine_dims.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace st::tune {

std::vector<nlohmann::json> engineNumbers(std::initializer_list<double> values) { return {values.begin(), values.end()}; }
std::vector<nlohmann::json> engineNames(std::initializer_list<const char*> values) { return {values.begin(), values.end()}; }

// The shadow distance and the split depths as shares of the far plane, as defaultSpace states them.
std::vector<nlohmann::json> engineDistances(const Settings& base) {
    std::vector<nlohmann::json> d{0.0};
    for (double share : {0.8, 0.65, 0.5, 0.4, 0.3, 0.22, 0.15, 0.12, 0.1, 0.08, 0.065}) d.emplace_back(farPlaneShare(base, share));
    return d;
}

std::vector<nlohmann::json> engineSplitDepths(const Settings& base) {
    std::vector<nlohmann::json> d;
    for (double share : {0.002, 0.004, 0.006, 0.01, 0.015, 0.02, 0.03, 0.04, 0.06, 0.08, 0.1, 0.13, 0.17, 0.22, 0.3, 0.4,
                         0.5, 0.65, 0.8})
        d.emplace_back(farPlaneShare(base, share));
    return d;
}

namespace {

void threejsDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({1, 2, 3, 4, 5, 6}));
    add("cascades.scheme", engineNames({"practical", "uniform", "logarithmic", "manual"}));  // practical is lambda 0.5
    add("cascades.shadowDistance", engineDistances(base));  // maxFar
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({256, 512, 1024, 2048, 4096}));  // shadowMapSize
    std::vector<nlohmann::json> margins;  // lightMargin - lightNear
    for (double share : kZExtensionShares) margins.emplace_back(farPlaneShare(base, share));
    margins.emplace_back(199.0);
    add("cascades.zExtensionDistance", margins);
    add("cascades.casterFaces", engineNames({"back", "both", "front"}));  // material.shadowSide
    add("filter.kind", engineNames({"pcf-vogel", "hard"}));                // PCFShadowMap, BasicShadowMap
    add("filter.radius", engineNumbers({0.0, 0.5, 1.0, 1.5, 2.0, 3.0}));   // light.shadow.radius
    // shadowBias x lightDepth (1999 m), toward the light: three.js's -1e-6 .. -1e-3.
    add("bias.constant", engineNumbers({-0.002, 0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0}));
    add("bias.normalOffset", engineNumbers({0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}));  // normalBias, metres
    for (int i = 0; i + 1 < kMaxTunedCascades; ++i)
        s.dims.push_back({"cascades.manualSplits[" + std::to_string(i) + "]", engineSplitDepths(base), true});  // custom breaks
}

void babylonDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({2, 3, 4}));                                    // numCascades
    add("cascades.lambda", engineNumbers({0.0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 1.0}));
    add("cascades.shadowDistance", engineDistances(base));                               // shadowMaxZ
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({256, 512, 1024, 2048, 4096}));
    // stabilizeCascades and depthClamp false are modelled only approximately (docs/engines.md):
    // the space keeps Babylon's defaults there, so what the tune says is what the engine does.
    add("cascades.blendBand", engineNumbers({0.0, 0.05, 0.1, 0.2}));                     // cascadeBlendPercentage
    // Not "none": Babylon stores half-float depth for it (NOTES.md), which the model does not (the
    // engine read 3.5 % misclassified where the model read 0.5 % on dutch-ship's tuned knobs).
    add("filter.kind", engineNames({"pcf-tent", "pcf2x2"}));                             // PCF high/medium, low
    add("filter.size", engineNumbers({3, 5}));
    // 1.5 x bias (depth clamp), in each box's normalised depth: Babylon's 5e-5 .. 5e-3.
    add("bias.constant", engineNumbers({0.000075, 0.00015, 0.0003, 0.00075, 0.0015, 0.003, 0.0075}));
    add("bias.normalOffset", engineNumbers({0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}));  // normalBias, metres
}

void godotDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({1, 2, 4}));                               // directional_shadow_mode
    add("cascades.shadowDistance", engineDistances(base));                          // directional_shadow_max_distance
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({512, 1024, 2048, 4096}));               // a quarter of the atlas
    std::vector<nlohmann::json> pancakes{0.0, 5.0, 10.0, 20.0};                    // directional_shadow_pancake_size
    for (double share : kZExtensionShares) pancakes.emplace_back(std::min(1024.0, farPlaneShare(base, share)));
    add("cascades.zExtensionDistance", pancakes);
    add("cascades.casterFaces", engineNames({"front", "back"}));                   // shadow_reverse_cull_face
    add("filter.kind", engineNames({"pcf-vogel", "pcf2x2"}));                      // soft qualities, hard
    add("filter.vogelTaps", engineNumbers({1, 4, 8, 16, 32}));                     // soft_shadow_filter_quality
    add("filter.radius", engineNumbers({0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0}));      // shadow_blur x quality radius
    add("bias.constant", engineNumbers({0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5}));  // metres in split 0: shadow_bias
    add("bias.normalOffset", engineNumbers({0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0}));  // shadow_normal_bias, texels
    for (int i = 0; i < 3; ++i)                                                    // split_1..3
        s.dims.push_back({"cascades.manualSplits[" + std::to_string(i) + "]", engineSplitDepths(base), true});
}

}  // namespace

Settings ontoEngine(xport::Engine e, const Settings& s) {
    nlohmann::json knobs = xport::knobsFor(e, s).knobs;
    if (e == xport::Engine::Babylon) {  // the knobs engineSpace keeps at their defaults
        knobs["stabilizeCascades"] = false;
        knobs["depthClamp"] = true;
    }
    return xport::engineModel(e, knobs, s);
}

Space engineSpace(xport::Engine e, const Settings& base) {
    Space s;
    switch (e) {
        case xport::Engine::ThreeJs: threejsDims(s, base); break;
        case xport::Engine::Babylon: babylonDims(s, base); break;
        case xport::Engine::Godot: godotDims(s, base); break;
        case xport::Engine::Unity: unityDims(s, base); break;
        case xport::Engine::Unreal: unrealDims(s, base); break;
        case xport::Engine::Bevy: bevyDims(s, base); break;
        case xport::Engine::Filament: filamentDims(s, base); break;
        default: throw std::invalid_argument(xport::engineName(e) + " has no tuning space yet");
    }
    s.project = [e](const Settings& x) { return ontoEngine(e, x); };
    for (Dimension& d : s.dims) {
        const auto starts = [&](const char* prefix) { return d.path.rfind(prefix, 0) == 0; };
        d.polish = starts("bias.") || d.path == "filter.radius" || starts("cascades.manualSplits") ||
                   d.path == "cascades.shadowDistance" || d.path == "cascades.blendBand" ||
                   d.path == "cascades.zExtensionDistance";
    }
    return s;
}


}  // namespace st::tune
