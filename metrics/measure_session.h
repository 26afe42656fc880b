#pragma once
// Measures one preset end to end (docs/architecture.md#how-the-product-is-measured):
// renders it, reads back the measurement pass, casts the ground truth, scores accuracy and
// texel density, times the passes, and replays the camera path for flicker. Needs a current
// GL 4.5 context. Scenes, their renderers and BVHs are kept per scene, so presets of one scene
// share them.
#include "metrics/accuracy.h"
#include "metrics/cost.h"
#include "metrics/flicker.h"
#include "metrics/ground_truth.h"
#include "metrics/map_warnings.h"
#include "metrics/soft_accuracy.h"
#include "metrics/texel_density.h"
#include "renderer/render/measure_pass.h"
#include "renderer/render/renderer.h"
#include "renderer/render/scene_cache.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace st::metrics {

struct MeasureTimings {  // wall-clock milliseconds
    double bvhMs = 0.0;          // BVH build (once per scene; 0 when it was cached)
    double groundTruthMs = 0.0;  // rays for every pixel
    double softTruthMs = 0.0;    // the sun's disc: measure.sunRays rays per receiver (0 when cached)
    double measurePassMs = 0.0;  // render + measurement pass + read-back
    double costMs = 0.0;
    double flickerMs = 0.0;
    double totalMs = 0.0;
};

struct PresetMeasurement {
    Settings settings;
    MeasureSamples samples;
    std::vector<std::uint8_t> truth;  // 1 lit, 0 shadowed, per pixel
    AccuracyReport accuracy;            // the nearest test against the point (centre-ray) truth
    SunDisc sun;                        // the disc the soft truth was traced for
    SoftTruth softTruth;                // visible fraction of the sun's disc, per pixel
    SoftAccuracyReport soft;            // the filtered result against the soft truth
    DensityReport density;
    std::optional<FlickerReport> flicker;  // when the preset has a path
    std::vector<float> flickerStdDev;      // per pixel, with flicker
    std::optional<CostReport> cost;
    FrameStats frame;                   // the measured frame's statistics (depth bounds, audit)
    std::vector<std::string> warnings;  // wasted maps and cut casters (metrics/map_warnings.h)
    MeasureTimings timings;
};

struct MeasureOptions {
    bool cost = true;
    // Timed frames, after one warm-up frame. 0: counted, not timed: the cost comes from the
    // measured frame's work with every map priced as redrawn (withEveryMapRedrawn), its timers are
    // NaN, and no frame is rendered for it (what a tune evaluation needs: the modelled cost).
    int costFrames = 5;
    const CostProfile* costProfile = nullptr;  // models the cost (CostReport::model) when set
    bool flicker = true;  // replay s.path when it has frames
    MapWarningLimits warningLimits;  // when a cascade's map counts as wasted
    std::function<void(const std::string&)> progress;  // one line per stage, if set
    // Draw with this renderer (made for the scene of entryFor(s)) instead of the scene's own: a
    // tune keeps one per view, so each view's maps stay drawn for candidates that differ only in
    // what the maps do not hold (filter, bias), instead of being redrawn at every change of view.
    Renderer* renderer = nullptr;
    // Off: the frames measured for the figures (the still and the path's) skip the main pass's
    // shading (RenderOptions::shadeMain): the figures come from the measurement pass and the
    // counted work is the same. Timed cost frames are always shaded.
    bool shadeMain = true;
    // RenderOptions::subpixelSteps of every frame measured (0: this GPU's own sub-pixel grid).
    int subpixelSteps = 0;
};

// The observer's world -> clip matrix: the preset camera at the output's aspect.
glm::mat4 observerViewProj(const Settings& s);

class MeasureSession {
public:
    // Measures `s`; relative glTF scene paths are resolved against presetDir. Throws
    // SceneError, std::invalid_argument (settings the cascade math rejects) or std::runtime_error.
    PresetMeasurement measure(const Settings& s, const std::filesystem::path& presetDir, const MeasureOptions& opt = {});

    // The scene, renderer and BVH for a scene spec; scene and renderer are created on first use,
    // the BVH (truth) by measure() when it first needs it.
    // One frame's traced truth and what it depends on. The truth is a function of the surface
    // samples, the sun and the eye only, not of any shadow setting, so points that share scene,
    // camera, light and size trace it once (compared exactly, not by key).
    struct CachedTruth {
        std::vector<glm::vec4> positions, normals, geometry;
        glm::vec3 toSun{0.0f}, eye{0.0f};
        std::vector<std::uint8_t> truth;
        // The soft truth of the same frame, for the disc it was traced with (the same inputs
        // plus light.angularDiameter and measure.sunRays; the seed is fixed).
        std::optional<SunDisc> disc;
        SoftTruth soft;
        SoftTruthRegions softRegions;  // of `soft` on these surfaces: what every candidate's scoring shares
        std::uint64_t surface = 0;     // MeasureSamples::surface of the samples last matched (0: none)
    };
    // A tune alternates between a few views; each keeps its truth (most recently used first).
    static constexpr std::size_t kCachedViews = 8;
    struct TruthSlot {
        std::unique_ptr<GroundTruth> truth;
        std::vector<CachedTruth> views;
    };
    using SceneEntry = SceneCache<TruthSlot>::Entry;
    SceneEntry& entryFor(const Settings& s, const std::filesystem::path& presetDir);
    MeasurePass& pass();

private:
    SceneCache<TruthSlot> scenes_;
    std::unique_ptr<MeasurePass> pass_;
};

// The sun's disc of `s` (light.angularDiameter, measure.sunRays, the fixed seed).
SunDisc sunDisc(const Settings& s);

// The per-frame pieces, for tests and tools that need only one figure.
// Renders `cascadeSettings` (its camera drives the cascades) and reads back what the observer
// of `observer` sees.
MeasureSamples sampleFrame(Renderer& r, MeasurePass& pass, const Settings& cascadeSettings, const Settings& observer,
                           FrameStats* stats = nullptr);
// Flicker of s.path seen by s.camera; `stdDev` receives the per-pixel hard standard deviation.
// With `truth` (the still truth of s.camera's pixels) the report has each frame's misclassified share.
FlickerReport measureFlicker(Renderer& r, MeasurePass& pass, const Settings& s, std::vector<float>* stdDev = nullptr,
                             const std::vector<std::uint8_t>& truth = {});
CostReport measureCost(Renderer& r, const Settings& s, int frames);
// The warnings of r's last render(s), whose statistics are `stats`: its z-extension audit, and
// texel density read back by one measurement pass (what `render` prints without a ground truth).
std::vector<std::string> frameWarnings(Renderer& r, MeasurePass& pass, const Settings& s, const FrameStats& stats,
                                       const MapWarningLimits& limits);
// Truth, accuracy and texel density of the frame `s` shows into `m` (the still part of
// MeasureSession::measure; the entry's BVH must exist).
void measureStill(MeasureSession::SceneEntry& e, MeasurePass& pass, const Settings& s, PresetMeasurement& m);
// ... drawn by `r`, a renderer of the entry's scene (MeasureOptions::renderer).
void measureStill(MeasureSession::SceneEntry& e, Renderer& r, MeasurePass& pass, const Settings& s, PresetMeasurement& m);

}  // namespace st::metrics
