// Godot 4's directional shadows (DirectionalLight3D properties and two project settings), as knobs
// and as shadowtune settings. Read from godotengine/godot (docs/engines.md "Godot 4" lists the files
// and commits): scene/3d/light_3d.cpp (the defaults), servers/rendering/renderer_scene_cull.cpp
// _light_instance_setup_directional_shadow (splits, spheres, depth range), renderer_rd/storage_rd/
// light_storage.cpp update_light_buffers (bias, normal bias, fade), renderer_scene_render_rd.cpp
// directional_soft_shadow_filter_set_quality (taps and radius per quality). Godot does not run here:
// this model is a reading of the source, never measured against the engine.
#include "renderer/csm/cascade_plan.h"
#include "renderer/csm/frustum.h"
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

constexpr const char* kAtlasSize = "rendering/lights_and_shadows/directional_shadow/size";
constexpr const char* kQuality = "rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality";
constexpr const char* kSplitNames[3] = {"directional_shadow_split_1", "directional_shadow_split_2", "directional_shadow_split_3"};

// directional_soft_shadow_filter_set_quality: directional_soft_shadow_samples and
// directional_shadow_quality_radius of hard, soft very low, low, medium, high, ultra.
constexpr std::array<int, 6> kGodotQualityTaps{0, 1, 4, 8, 16, 32};
constexpr std::array<float, 6> kGodotQualityRadius{1.0f, 1.5f, 2.0f, 2.0f, 3.0f, 4.0f};

// Light3D::Light3D and DirectionalLight3D::DirectionalLight3D; the project settings' defaults.
json godotDefaults() {
    return {{"directional_shadow_mode", 2},           {kSplitNames[0], 0.1},
            {kSplitNames[1], 0.2},                    {kSplitNames[2], 0.5},
            {"directional_shadow_max_distance", 100.0}, {"directional_shadow_pancake_size", 20.0},
            {"directional_shadow_blend_splits", false}, {"directional_shadow_fade_start", 0.8},
            {"shadow_bias", 0.1},                     {"shadow_normal_bias", 2.0},
            {"shadow_blur", 1.0},                     {"shadow_reverse_cull_face", false},
            {kAtlasSize, 4096},                       {kQuality, 2}};
}

int splitsOfMode(int mode) { return mode == 0 ? 1 : mode == 1 ? 2 : 4; }  // ORTHOGONAL, PARALLEL_2, PARALLEL_4

// The radius of split i's sphere: centred on the mean of the slice's 8 corners, the farthest corner
// as radius, widened by a texel each side (radius *= size / (size - 2)); with blend splits a split
// starts where the previous one does (renderer_scene_cull.cpp).
float sphereRadius(const Settings& s, const std::vector<float>& splits, int i, bool blend) {
    const float aspect = float(s.output.width) / float(std::max(1, s.output.height));
    const csm::CameraParams cam = csm::cameraFromSettings(s.camera, aspect);
    const float from = splits[std::size_t(blend && i > 0 ? i - 1 : i)];
    const csm::Corners corners = csm::sliceCornersFromCamera(cam, from, splits[std::size_t(i) + 1]);
    glm::vec3 mean(0.0f);
    for (const glm::vec3& p : corners) mean += p / 8.0f;
    float r = 0.0f;
    for (const glm::vec3& p : corners) r = std::max(r, glm::length(p - mean));
    const float size = float(s.cascades.mapSize);
    return r * size / (size - 2.0f);
}

// The depth bias in metres of each split: shadow_bias / 100 x bias_scale x soft_shadow_scale, where
// bias_scale = the split's light depth range (2 r + pancake) and soft_shadow_scale = shadow_blur x
// the quality radius (light_storage.cpp update_light_buffers).
std::vector<float> depthBiasPerSplit(const Settings& s, double shadowBias, double softScale, float pancake, bool blend) {
    const std::vector<float> splits = presetSplits(s);
    std::vector<float> out;
    for (int i = 0; i < s.cascades.count; ++i)
        out.push_back(float(shadowBias / 100.0 * (2.0 * sphereRadius(s, splits, i, blend) + pancake) * softScale));
    return out;
}

void setFilter(Settings& s, int quality, float blur) {
    FilterSettings& f = s.filter;
    f = FilterSettings{};
    if (quality == 0) {  // hard: one hardware-compared, bilinear tap
        f.kind = FilterKind::Pcf2x2;
        return;
    }
    // Vogel-disk taps rotated per pixel (scene_forward_clustered.glsl), radius shadow_blur x the
    // quality radius in texels. Approximate: Godot rotates by its own hash and shrinks the radius by
    // split_0 / split_i in the later splits.
    f.kind = FilterKind::Vogel;
    f.vogelTaps = kGodotQualityTaps[std::size_t(quality)];
    f.radius = blur * kGodotQualityRadius[std::size_t(quality)];
}

}  // namespace

json godotDefaultKnobs() { return godotDefaults(); }

Settings godotModel(const json& given, const Settings& view) {
    const json k = withDefaults(godotDefaults(), given);
    Settings s = view;
    CascadeSettings& c = s.cascades;
    c = CascadeSettings{};
    c.count = splitsOfMode(knobInt(k, "directional_shadow_mode", 0, 2));
    const float maxDistance = knobFloat(k, "directional_shadow_max_distance", 0.1, 1e7);
    const float end = std::min(maxDistance, view.camera.farPlane);
    c.shadowDistance = maxDistance < view.camera.farPlane ? maxDistance : 0.0f;
    c.scheme = SplitScheme::Manual;
    // distances[i + 1] = near + split_i x (max - near) (renderer_scene_cull.cpp).
    float previous = 0.0f;
    for (int i = 0; i + 1 < c.count; ++i) {
        const int slot = c.count == 2 ? 0 : i;
        const float f = knobFloat(k, kSplitNames[slot], 0.0, 1.0);
        if (f <= previous || f >= 1.0f)
            throw std::invalid_argument(std::string("settings.") + kSplitNames[slot] + ": " + k.at(kSplitNames[slot]).dump() +
                                        " must lie above the previous split and below 1");
        previous = f;
        c.manualSplits.push_back(view.camera.nearPlane + f * (end - view.camera.nearPlane));
    }
    const int atlas = knobInt(k, kAtlasSize, 256, 16384);
    c.mapSize = c.count == 1 ? atlas : atlas / 2;  // quadrants; 2 splits are size x size/2 rects (approximate)
    c.fit = FitMode::Sphere;  // approximate: shadowtune's sphere is the smallest one, snapped to one texel
    c.stabilize = true;
    const float pancake = knobFloat(k, "directional_shadow_pancake_size", 0.0, 1024.0);
    c.zExtension = pancake > 0.0f ? ZExtension::Distance : ZExtension::None;  // the reach; the clamp is not modelled
    c.zExtensionDistance = pancake;
    c.selection = Selection::Interval;
    const bool blend = k.at("directional_shadow_blend_splits").get<bool>();
    c.blendBand = blend ? 0.1f : 0.0f;  // approximate: Godot blends across the whole overlap
    // fade_from = max x min(fade_start, 0.999) .. max, a smoothstep (approximate: linear here).
    const float fadeStart = knobFloat(k, "directional_shadow_fade_start", 0.0, 1.0);
    const float lastStart = c.manualSplits.empty() ? view.camera.nearPlane : c.manualSplits.back();
    c.fadeBand = fadeStart >= 0.999f ? 0.0f : std::min(1.0f, (1.0f - fadeStart) * end / (end - lastStart));
    // GeometryInstance3D.cast_shadow ON casts the faces the material draws (cull back: the front faces
    // toward the light); Light3D.shadow_reverse_cull_face draws the back faces instead.
    c.casterFaces = k.at("shadow_reverse_cull_face").get<bool>() ? CasterFaces::Back : CasterFaces::Front;
    const int quality = knobInt(k, kQuality, 0, 5);
    const float blur = knobFloat(k, "shadow_blur", 0.0, 10.0);
    setFilter(s, quality, blur);
    BiasSettings& b = s.bias;
    b = BiasSettings{};
    b.slope = 0.0f;
    b.normalOffset = knobFloat(k, "shadow_normal_bias", 0.0, 10.0);  // x the split's texel (light_storage.cpp)
    b.normalOffsetUnit = OffsetUnit::Texels;
    const std::vector<float> depth =
        depthBiasPerSplit(s, knobFloat(k, "shadow_bias", 0.0, 10.0), blur * kGodotQualityRadius[std::size_t(quality)], pancake, blend);
    b.constant = depth.front();
    b.constantUnit = BiasUnit::Metres;
    if (c.count > 1 && b.constant > 0.0f)
        for (float d : depth) b.constantScale.push_back(d / b.constant);
    return s;
}

namespace {

int qualityOf(const FilterSettings& f, std::vector<std::string>& lacks) {
    switch (f.kind) {
        case FilterKind::Pcf2x2: return 0;
        case FilterKind::Vogel: {
            int q = 1;
            for (int i = 1; i < 6; ++i)
                if (std::abs(kGodotQualityTaps[std::size_t(i)] - f.vogelTaps) < std::abs(kGodotQualityTaps[std::size_t(q)] - f.vogelTaps)) q = i;
            if (kGodotQualityTaps[std::size_t(q)] != f.vogelTaps)
                lacks.push_back(std::to_string(f.vogelTaps) + " Vogel taps: Godot's qualities take 1, 4, 8, 16 or 32");
            return q;
        }
        default:
            lacks.push_back("filter '" + enumName(f.kind) + "': Godot filters with Vogel-disk taps (soft low instead)");
            return 2;
    }
}

void splitKnobs(json& k, const Settings& s, std::vector<std::string>& lacks) {
    const CascadeSettings& c = s.cascades;
    const int n = c.count;
    k["directional_shadow_mode"] = n == 1 ? 0 : n == 2 ? 1 : 2;
    if (n != 1 && n != 2 && n != 4) lacks.push_back(std::to_string(n) + " cascades: Godot has 1, 2 or 4 splits");
    const std::vector<float> splits = presetSplits(s);
    const double near = splits.front(), end = splits.back();
    k["directional_shadow_max_distance"] = round6(c.shadowDistance > 0.0f ? c.shadowDistance : s.camera.farPlane);
    const auto fraction = [&](std::size_t i) { return round6((double(splits[i]) - near) / (end - near)); };
    if (n == 2) k[kSplitNames[0]] = fraction(1);
    for (int i = 0; n >= 3 && i < 3; ++i)
        k[kSplitNames[i]] = std::size_t(i) + 2 < splits.size() ? fraction(std::size_t(i) + 1)
                                                               : round6(0.5 * (fraction(splits.size() - 2) + 1.0));
}

}  // namespace

EngineKnobs godotKnobsFor(const Settings& s) {
    EngineKnobs out{godotDefaults(), {}};
    json& k = out.knobs;
    const CascadeSettings& c = s.cascades;
    splitKnobs(k, s, out.lacks);
    k[kAtlasSize] = c.count == 1 ? c.mapSize : c.mapSize * 2;
    if (c.fit != FitMode::Sphere || !c.stabilize) out.lacks.push_back("fit '" + enumName(c.fit) + "': Godot fits a snapped sphere per split");
    // As export_godot.cpp: 0 turns Godot's clamp off, so shadowtune's pancake (clamp, no reach) is
    // the editor's smallest step, 0.1 m.
    float pancake = 20.0f;
    if (c.zExtension == ZExtension::Distance) pancake = c.zExtensionDistance;
    else if (c.zExtension == ZExtension::None) pancake = 0.0f;
    else if (c.zExtension == ZExtension::Pancake) pancake = 0.1f;
    else out.lacks.push_back("z extension '" + enumName(c.zExtension) + "': Godot reaches pancake_size toward the sun");
    k["directional_shadow_pancake_size"] = round6(pancake);
    if (c.selection != Selection::Interval) out.lacks.push_back("map-based cascade selection: Godot picks by view depth");
    k["directional_shadow_blend_splits"] = c.blendBand > 0.0f;
    const std::vector<float> splits = presetSplits(s);
    const double end = splits.back(), lastStart = splits[splits.size() - 2];
    k["directional_shadow_fade_start"] = c.fadeBand > 0.0f ? round6(1.0 - double(c.fadeBand) * (end - lastStart) / end) : 1.0;
    if (c.casterFaces == CasterFaces::Both) out.lacks.push_back("both faces casting: Godot casts the front faces, or the back ones reversed");
    k["shadow_reverse_cull_face"] = c.casterFaces == CasterFaces::Back;
    const int quality = qualityOf(s.filter, out.lacks);
    k[kQuality] = quality;
    const double blur = s.filter.kind == FilterKind::Vogel ? double(s.filter.radius) / kGodotQualityRadius[std::size_t(quality)] : 1.0;
    k["shadow_blur"] = round6(blur);
    const BiasSettings& b = s.bias;
    if (b.constantUnit != BiasUnit::Metres) out.lacks.push_back("a bias in the box's depth: Godot's grows with each split's range");
    const std::vector<float> perUnit =
        depthBiasPerSplit(s, 100.0, blur * kGodotQualityRadius[std::size_t(quality)], pancake, c.blendBand > 0.0f);
    k["shadow_bias"] = perUnit.front() > 0.0f ? round6(100.0 * std::max(0.0f, b.constant) / perUnit.front()) : 0.0;
    if (b.constant < 0.0f) out.lacks.push_back("a bias away from the light");
    for (int i = 1; i < c.count && !b.constantScale.empty(); ++i)
        if (std::abs(cascadeFactor(b.constantScale, i) - perUnit[std::size_t(i)] / perUnit.front()) > 0.01f) {
            out.lacks.push_back("a constant bias per cascade: Godot's grows with each split's depth range by itself");
            break;
        }
    if (!b.slopeScale.empty() || !b.normalOffsetScale.empty()) out.lacks.push_back("slope or normal bias per cascade");
    if (b.normalOffsetUnit == OffsetUnit::Texels) k["shadow_normal_bias"] = round6(b.normalOffset);
    else out.lacks.push_back("normal offset in metres: Godot's shadow_normal_bias is in texels");
    if (b.slope > 0.0f) out.lacks.push_back("slope-scaled bias");
    if (b.receiverPlane) out.lacks.push_back("receiver-plane bias");
    return out;
}

const KnobTable& godotTable() {
    static const KnobTable table{
        godotDefaultKnobs, godotModel, godotKnobsFor, godotSnippets,
        {{"directional_shadow_split_1", "share of max distance"}, {"directional_shadow_split_2", "share of max distance"},
         {"directional_shadow_split_3", "share of max distance"}, {"directional_shadow_max_distance", "m"},
         {"directional_shadow_pancake_size", "m"}, {"directional_shadow_fade_start", "share of max distance"},
         {"shadow_bias", "x split depth range / 100"}, {"shadow_normal_bias", "texels"},
         {"rendering/lights_and_shadows/directional_shadow/size", "texels"}},
        // DirectionalLight3D and the directional shadow project settings.
        {"cascades.count", "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize",
         "cascades.zExtensionDistance", "cascades.blendBand", "cascades.fadeBand", "cascades.casterFaces", "filter.kind",
         "filter.vogelTaps", "filter.radius", "bias.constant", "bias.normalOffset"}};
    return table;
}

}  // namespace st::xport
