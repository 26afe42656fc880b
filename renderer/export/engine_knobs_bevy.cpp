// Bevy's directional shadows (CascadeShadowConfig, DirectionalLight, the DirectionalLightShadowMap
// resource and the camera's ShadowFilteringMethod), as knobs and as shadowtune settings. Read from
// bevyengine/bevy at 4805ca79 (0.20.0-dev; docs/engines.md "Bevy" has the table of lines):
// crates/bevy_light/src/cascade.rs (CascadeShadowConfig :26-33, the builder's defaults :135-158,
// build_directional_light_cascades :234-238, calculate_cascade :284-299), crates/bevy_light/src/
// directional_light.rs (biases :165-167, map size :202-213), crates/bevy_pbr/src/render/light.rs
// (MAX_CASCADES_PER_LIGHT :243, normal bias x sqrt 2 :879-880), crates/bevy_pbr/src/render/
// shadows.wesl (selection :134-143, offsets :188-191, blend :244-258), shadow_sampling.wesl (filters).
// Bevy does not run here: this model is a reading of the source, never measured against the engine.
#include "renderer/csm/cascade_plan.h"
#include "renderer/csm/frustum.h"
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"
#include "renderer/settings/number_text.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

constexpr int kBevyCascadeLimit = 4;  // light.rs:243 MAX_CASCADES_PER_LIGHT (1 on WebGL 2)
constexpr int kBevyTemporalTaps = 8;  // shadow_sampling.wesl:173-205, 8 spiral offsets

// CascadeShadowConfigBuilder::default built (cascade.rs:41-56, 135-158: bounds 10 x 15^(i/3), the
// preset's 5 decimals, within 1e-5 m of Bevy's f32 values), DirectionalLight::default
// (directional_light.rs:147-167), DirectionalLightShadowMap::default (:202-206) and
// ShadowFilteringMethod's #[default] (crates/bevy_light/src/lib.rs:305-306). The keys are the
// Rust field names the snippet writes (shadow_map_size: DirectionalLightShadowMap.size).
json bevyDefaults() {
    return {{"bounds", {10.0, 24.66212, 60.82202, 150.0}},
            {"overlap_proportion", 0.2},
            {"minimum_distance", 0.1},
            {"shadow_depth_bias", 0.02},
            {"shadow_normal_bias", 1.8},
            {"shadow_map_size", 2048},
            {"shadow_filtering_method", "Gaussian"}};
}

// CascadeShadowConfig.bounds: the far bound of each cascade, increasing, the last one where the
// shadows end (fetch_directional_shadow returns lit past it, shadows.wesl:230-234).
std::vector<float> bevyBounds(const json& k, const Settings& view) {
    const json& b = k.at("bounds");
    if (!b.is_array() || b.empty() || b.size() > std::size_t(kBevyCascadeLimit))
        throw std::invalid_argument("settings.bounds: 1 to 4 far bounds (MAX_CASCADES_PER_LIGHT), got " + b.dump());
    float previous = knobFloat(k, "minimum_distance", 0.0, 1e6);
    std::vector<float> out;
    for (std::size_t i = 0; i < b.size(); ++i) {
        if (!b[i].is_number() || !std::isfinite(b[i].get<double>()) || b[i].get<float>() <= previous)
            throw std::invalid_argument("settings.bounds[" + std::to_string(i) + "]: " + b[i].dump() +
                                        " must be a number beyond minimum_distance and the bound before it");
        previous = b[i].get<float>();
        out.push_back(previous);
        // The cascades after one ending at or past the camera's far plane hold no visible pixel
        // (Bevy's defaults, 10 .. 150 m, in a 20 m room): shadowtune's splits end at the far plane,
        // so they are left out. Approximate: Bevy still draws their passes (a cost not modelled).
        if (previous >= view.camera.farPlane) break;
    }
    return out;
}

// Bevy blends cascade j into j + 1 over [(1 - overlap) z_j, z_j] (shadows.wesl:244-258), a share
// overlap x z_j / (z_j - z_{j-1}) of shadowtune's cascade j. One band for every cascade here, so
// it is converted on the second cascade (the first with 1 or 2), as export_bevy.cpp does: exact
// for the interior cascades when the bounds are geometric. Capped at the field's 0.5.
float bevyBlendBand(double overlap, const std::vector<float>& splits) {
    const std::size_t count = splits.size() - 1;
    if (count < 2) return 0.0f;
    const std::size_t j = count >= 3 ? 2 : 1;
    return float(std::min(0.5, round6(overlap * splits[j] / (double(splits[j]) - splits[j - 1]))));
}

// Bevy's Temporal filter (shadow_sampling.wesl:165-171): 8 spiral taps out to f(t) / (t x size) in
// uv, t = cascade.texel_size = ceil(diameter) / size (cascade.rs:284-291) and f the "empirically
// chosen fudge factor" map(0.00390625, 0.022949219, 0.015, 0.035, t): a disc of f metres. As
// shadowtune texels of cascade 0's unrounded box: f x size / diameter. Approximate: one radius for
// every cascade (Bevy's f follows each cascade's texel), and the rotation is still, not per frame.
float bevyTemporalRadius(const Settings& s) {
    const std::vector<float> splits = presetSplits(s);
    const float aspect = float(s.output.width) / float(std::max(1, s.output.height));
    const csm::Corners w = csm::sliceCornersFromCamera(csm::cameraFromSettings(s.camera, aspect), splits[0], splits[1]);
    const double diameter = std::max(glm::distance(w[6], w[4]), glm::distance(w[6], w[0]));  // far face, body
    const double size = double(s.cascades.mapSize);
    const double texel = std::ceil(diameter) / size;
    const double f = 0.015 + (texel - 0.00390625) * (0.035 - 0.015) / (0.022949219 - 0.00390625);
    return float(round6(f * size / diameter));
}

void bevyFilter(Settings& s, const std::string& method) {
    FilterSettings& f = s.filter;
    f = FilterSettings{};
    if (method == "Hardware2x2") {
        f.kind = FilterKind::Pcf2x2;  // one hardware-compared bilinear tap (shadow_sampling.wesl:9-25)
    } else if (method == "Gaussian") {
        // Castano's 9 bilinear taps over 5 x 5 texels (sample_shadow_map_castano_thirteen,
        // shadow_sampling.wesl:101-143): the same weights and offsets as shadowtune's tent of 5.
        f.kind = FilterKind::Tent;
        f.size = 5;
    } else if (method == "Temporal") {
        f.kind = FilterKind::Vogel;  // Jimenez's spiral, rotated per pixel by interleaved gradient noise
        f.vogelTaps = kBevyTemporalTaps;
        f.radius = bevyTemporalRadius(s);
    } else {
        throw std::invalid_argument("settings.shadow_filtering_method: '" + method + "' is not Hardware2x2, Gaussian or Temporal");
    }
}

}  // namespace

json bevyDefaultKnobs() { return bevyDefaults(); }

Settings bevyModel(const json& given, const Settings& view) {
    const json k = withDefaults(bevyDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    // minimum_distance is checked but not modelled: shadowtune's first cascade starts at the camera
    // near plane, Bevy's at minimum_distance (cascade.rs:236); the box of cascade 0 is its far
    // face's width either way unless minimum_distance is large (the builder's note, cascade.rs:76-80).
    const std::vector<float> bounds = bevyBounds(k, view);
    c.count = int(bounds.size());
    c.scheme = SplitScheme::Manual;
    c.manualSplits.assign(bounds.begin(), bounds.end() - 1);
    c.shadowDistance = bounds.back() < view.camera.farPlane ? bounds.back() : 0.0f;
    // validate_shadow_map_size (directional_light.rs:208-213) rounds the size up to a power of two.
    const int size = knobInt(k, "shadow_map_size", 256, 8192);
    c.mapSize = 1;
    while (c.mapSize < size) c.mapSize *= 2;
    // calculate_cascade (cascade.rs:284-299): a square as wide as the slice's longer diagonal (body
    // or far face), its centre floored to texels, the near plane at the slice, casters in front kept
    // by unclipped depth (crates/bevy_pbr/src/prepass/mod.rs:427-492). Approximate: Bevy rounds the
    // width up to whole metres, and its cascades' slices overlap by overlap_proportion.
    c.fit = FitMode::Diagonal;
    c.stabilize = true;
    c.snap = Snap::CentreFloor;
    c.zExtension = ZExtension::Pancake;
    c.selection = Selection::Interval;  // get_cascade_index: the first far bound beyond the depth
    std::vector<float> splits{view.camera.nearPlane};
    splits.insert(splits.end(), bounds.begin(), bounds.end());
    splits.back() = std::min(splits.back(), view.camera.farPlane);
    c.blendBand = bevyBlendBand(knobFloat(k, "overlap_proportion", 0.0, 0.99), splits);  // Bevy asserts [0, 1)
    // StandardMaterial's cull_mode Some(Face::Back) (crates/bevy_pbr/src/pbr_material.rs:926) holds in
    // the shadow pass too (specialize, :1550-1559): casters draw their faces toward the sun.
    c.casterFaces = CasterFaces::Front;
    bevyFilter(s, k.at("shadow_filtering_method").get<std::string>());
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    b.slope = 0.0f;  // Bevy has no slope-scaled bias
    // shadows.wesl:188-191: the receiver moves shadow_depth_bias metres toward the light and
    // shadow_normal_bias x sqrt 2 (light.rs:879-880) x the cascade's texel along its normal.
    b.constant = knobFloat(k, "shadow_depth_bias", -10.0, 10.0);
    b.constantUnit = BiasUnit::Metres;
    b.normalOffset = float(double(knobFloat(k, "shadow_normal_bias", 0.0, 100.0)) * std::sqrt(2.0));
    b.normalOffsetUnit = OffsetUnit::Texels;
    return s;
}

EngineKnobs bevyKnobsFor(const Settings& s) {
    EngineKnobs out{bevyDefaults(), {}};
    json& k = out.knobs;
    std::vector<std::string>& lacks = out.lacks;
    const CascadeSettings& c = s.cascades;
    const std::vector<float> splits = presetSplits(s);
    const int used = std::min(c.count, kBevyCascadeLimit);
    if (c.count > kBevyCascadeLimit) lacks.push_back(std::to_string(c.count) + " cascades: Bevy draws at most 4 per light");
    json bounds = json::array();
    for (int i = 1; i < used; ++i) bounds.push_back(tidyFloat(splits[std::size_t(i)]));
    bounds.push_back(tidyFloat(splits.back()));
    k["bounds"] = bounds;
    k["minimum_distance"] = tidyFloat(s.camera.nearPlane);  // where shadowtune's first cascade starts
    if (c.depthBounds != DepthBounds::Off) lacks.push_back("depth-bounds fit: Bevy's bounds are fixed distances");
    if (used > 1) {
        const std::size_t j = used >= 3 ? 2 : 1;
        k["overlap_proportion"] = round6(double(c.blendBand) * (double(splits[j]) - splits[j - 1]) / splits[j]);
    }
    k["shadow_map_size"] = c.mapSize;
    if (!c.mapSizes.empty()) lacks.push_back("a map size per cascade: Bevy's DirectionalLightShadowMap.size is one");
    if (c.fit != FitMode::Diagonal || !c.stabilize || c.snap != Snap::CentreFloor)
        lacks.push_back("fit '" + enumName(c.fit) + "': Bevy fits a diagonal-wide square, its centre floored to texels");
    if (c.zExtension != ZExtension::Pancake || c.pancakeToCasters)
        lacks.push_back("z extension '" + enumName(c.zExtension) + "': Bevy's box starts at the slice, casters in front clamped");
    if (c.selection != Selection::Interval) lacks.push_back("map-based cascade selection: Bevy picks by view depth");
    if (c.casterFaces != CasterFaces::Front) lacks.push_back("caster faces '" + enumName(c.casterFaces) + "': Bevy's materials cull back faces");
    if (c.fadeBand > 0.0f) lacks.push_back("a far fade: Bevy's shadows end at the last bound");
    const FilterSettings& f = s.filter;
    if (f.kind == FilterKind::Pcf2x2) k["shadow_filtering_method"] = "Hardware2x2";
    else if (f.kind == FilterKind::Tent && f.size == 5) k["shadow_filtering_method"] = "Gaussian";
    else if (f.kind == FilterKind::Vogel) {
        k["shadow_filtering_method"] = "Temporal";
        if (f.vogelTaps != kBevyTemporalTaps || std::abs(f.radius - bevyTemporalRadius(s)) > 0.01f * f.radius)
            lacks.push_back("a Vogel disc of " + std::to_string(f.vogelTaps) + " taps, radius " + formatFloat(f.radius) +
                            ": Bevy's Temporal takes 8 taps over " + formatFloat(bevyTemporalRadius(s)) + " texels here");
    } else lacks.push_back("filter '" + enumName(f.kind) + "': Bevy filters Hardware2x2, Gaussian (tent 5) or Temporal");
    if (f.contact != ContactShadows::Off || f.screenSpace != ScreenSpace::Off)
        lacks.push_back("contact shadows or screen-space blur: not in Bevy's knob table");
    const BiasSettings& b = s.bias;
    if (b.constantUnit == BiasUnit::Metres) k["shadow_depth_bias"] = round6(b.constant);
    else lacks.push_back("a bias in the box's depth: Bevy's shadow_depth_bias is metres");
    if (b.normalOffsetUnit == OffsetUnit::Texels) k["shadow_normal_bias"] = round6(b.normalOffset / std::sqrt(2.0));
    else lacks.push_back("normal offset in metres: Bevy's shadow_normal_bias is x sqrt 2 cascade texels");
    if (b.slope > 0.0f) lacks.push_back("slope-scaled bias");
    if (b.receiverPlane) lacks.push_back("receiver-plane bias");
    if (hasCascadeBias(b)) lacks.push_back("bias per cascade");
    return out;
}

const KnobTable& bevyTable() {
    static const KnobTable table{
        bevyDefaultKnobs, bevyModel, bevyKnobsFor, bevySnippets,
        {{"bounds", "m"}, {"minimum_distance", "m"}, {"overlap_proportion", "share of a far bound"},
         {"shadow_depth_bias", "m"}, {"shadow_normal_bias", "x sqrt 2 cascade texels"}, {"shadow_map_size", "texels"}},
        // CascadeShadowConfig, DirectionalLight, DirectionalLightShadowMap and ShadowFilteringMethod.
        {"cascades.count", "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize", "cascades.blendBand",
         "filter.kind", "bias.constant", "bias.normalOffset"}};
    return table;
}

}  // namespace st::xport
