// The tuning spaces of Unity URP and Unreal Engine 5 (tune --engine unity|unreal): their knobs'
// candidates in shadowtune's settings, projected onto what the engine takes by its model
// (renderer/export/engine_knobs_unity.cpp, engine_knobs_unreal.cpp). Neither engine runs here.
#include "tune/tune_engine_dims.h"

#include <string>

namespace st::tune {

void unityDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({1, 2, 3, 4}));                         // m_ShadowCascadeCount
    add("cascades.shadowDistance", engineDistances(base));                       // m_ShadowDistance
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({256, 512, 1024, 2048, 4096}));       // the atlas, or half its side
    add("cascades.fadeBand", engineNumbers({0.0, 0.05, 0.1, 0.2, 0.4}));         // m_CascadeBorder
    add("filter.kind", engineNames({"pcf2x2", "pcf-tent"}));                     // soft shadows off, on
    add("filter.size", engineNumbers({3, 5}));                                   // soft quality low, medium
    add("bias.constant", engineNumbers({0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5}));  // m_ShadowDepthBias x texel
    add("bias.normalOffset", engineNumbers({0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0}));  // m_ShadowNormalBias, texels
    for (int i = 0; i < 3; ++i)                                                  // m_Cascade2/3/4Split
        s.dims.push_back({"cascades.manualSplits[" + std::to_string(i) + "]", engineSplitDepths(base), true});
}

void unrealDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({1, 2, 3, 4, 5, 6}));                   // DynamicShadowCascades
    add("cascades.shadowDistance", engineDistances(base));                       // DynamicShadowDistanceMovableLight
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({512, 1024, 2048, 4096}));            // r.Shadow.MaxCSMResolution
    add("cascades.blendBand", engineNumbers({0.0, 0.05, 0.1, 0.2, 0.3}));       // CascadeTransitionFraction
    add("cascades.fadeBand", engineNumbers({0.0, 0.1, 0.2, 0.4}));              // ShadowDistanceFadeoutFraction
    add("filter.kind", engineNames({"pcf-nxn", "pcf2x2", "hard"}));             // r.ShadowQuality 3-5, 2, 1
    add("filter.size", engineNumbers({3, 5}));
    add("bias.constant", engineNumbers({0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5}));  // ShadowBias x 5 texels
    add("bias.slope", engineNumbers({0.0, 0.5, 1.0, 2.0, 3.75, 6.0, 10.0}));    // ShadowSlopeBias x ShadowBias x 15
    // CascadeDistributionExponent: the first split moves it (the projection fits the exponent).
    s.dims.push_back({"cascades.manualSplits[0]", engineSplitDepths(base), true});
}

}  // namespace st::tune
