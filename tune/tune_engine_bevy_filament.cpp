// The tuning spaces of Bevy and Filament: their knobs (renderer/export/engine_knobs_bevy.cpp,
// engine_knobs_filament.cpp) as candidate values of the Settings fields they set, in the engines'
// units (metres, texels of the engine's own definition).
#include "tune/tune_engine_dims.h"

#include <string>

namespace st::tune {

void bevyDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({1, 2, 3, 4}));                     // bounds.len(), MAX_CASCADES_PER_LIGHT 4
    add("cascades.shadowDistance", engineDistances(base));                   // the last bound
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({512, 1024, 2048, 4096}));         // DirectionalLightShadowMap.size
    // overlap_proportion as shadowtune's band (0.2 on geometric bounds is 0.336 of a cascade).
    add("cascades.blendBand", engineNumbers({0.0, 0.05, 0.1, 0.2, 0.336406, 0.5}));
    add("filter.kind", engineNames({"pcf-tent", "pcf2x2", "pcf-vogel"}));   // Gaussian, Hardware2x2, Temporal
    add("bias.constant", engineNumbers({0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}));  // shadow_depth_bias, metres
    // shadow_normal_bias x sqrt 2, in cascade texels: Bevy's 0 .. 3.5 (default 1.8).
    add("bias.normalOffset", engineNumbers({0.0, 0.707107, 1.414214, 2.12132, 2.545584, 3.535534, 4.949747}));
    for (int i = 0; i < 3; ++i)                                              // the interior bounds
        s.dims.push_back({"cascades.manualSplits[" + std::to_string(i) + "]", engineSplitDepths(base), true});
}

void filamentDims(Space& s, const Settings& base) {
    auto add = [&](std::string path, std::vector<nlohmann::json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", engineNumbers({1, 2, 3, 4}));                     // shadowCascades
    add("cascades.shadowDistance", engineDistances(base));                   // shadowFar
    s.dims.back().jumps = true;
    add("cascades.mapSize", engineNumbers({512, 1024, 2048, 4096}));         // mapSize
    add("cascades.fit", engineNames({"cascade", "sphere"}));                 // stable false, true
    // PCF only: VSM and PCSS are modelled with shadowtune's own parameters, not Filament's
    // (VsmShadowOptions, SoftShadowOptions), so a tune there would say little about Filament.
    add("bias.constant", engineNumbers({0.0, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05}));  // constantBias, m
    add("bias.slope", engineNumbers({0.0, 0.5, 1.0, 2.0, 3.0, 4.0}));       // polygonOffsetSlope
    add("bias.normalOffset", engineNumbers({0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0}));  // normalBias / 2, texels
    for (int i = 0; i < 3; ++i)                                              // cascadeSplitPositions
        s.dims.push_back({"cascades.manualSplits[" + std::to_string(i) + "]", engineSplitDepths(base), true});
}

}  // namespace st::tune
