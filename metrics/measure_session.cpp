#include "metrics/measure_session.h"

#include "metrics/camera_path.h"
#include "metrics/map_warnings.h"
#include "metrics/resolution_check.h"
#include "renderer/csm/cascade_plan.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

namespace st::metrics {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

void report(const MeasureOptions& opt, const std::string& line) {
    if (opt.progress) opt.progress(line);
}

std::string seconds(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", ms / 1000.0);
    return text;
}

}  // namespace

glm::mat4 observerViewProj(const Settings& s) {
    const csm::CameraParams cam = csm::cameraFromSettings(s.camera, float(s.output.width) / float(s.output.height));
    return csm::projectionMatrix(cam) * csm::viewMatrix(cam);
}

MeasureSession::SceneEntry& MeasureSession::entryFor(const Settings& s, const fs::path& presetDir) {
    return scenes_.entryFor(s, presetDir);
}

MeasurePass& MeasureSession::pass() {
    if (!pass_) pass_ = std::make_unique<MeasurePass>();
    return *pass_;
}

MeasureSamples sampleFrame(Renderer& r, MeasurePass& pass, const Settings& cascadeSettings, const Settings& observer,
                           FrameStats* stats) {
    FrameStats frame = r.render(cascadeSettings);
    if (stats) *stats = std::move(frame);
    return pass.run(r, cascadeSettings, observerViewProj(observer));
}

FlickerReport measureFlicker(Renderer& r, MeasurePass& pass, const Settings& s, std::vector<float>* stdDev,
                             const std::vector<std::uint8_t>& truth) {
    if (s.path.frames <= 0) return {};
    const MeasureSamples first = sampleFrame(r, pass, atPathFrame(s, 0), s);  // fixes the sample points
    FlickerMeter meter(first, truth, s.light.intensity);
    meter.add(first.shadow);
    for (int frame = 1; frame < s.path.frames; ++frame) {
        const Settings cascadeSettings = atPathFrame(s, frame);
        r.render(cascadeSettings);
        meter.add(pass.runShadowOnly(r, cascadeSettings, observerViewProj(s)));
    }
    if (stdDev) *stdDev = meter.hardStdDev();
    return meter.report();
}

CostReport measureCost(Renderer& r, const Settings& s, int frames) {
    // The cost of drawing the maps, not of keeping them: a still camera would redraw nothing.
    const RenderOptions options = r.options();
    RenderOptions redrawAll = options;
    redrawAll.cacheMaps = false;
    r.setOptions(redrawAll);
    r.render(s);  // warm-up: first-use allocations and shader variants
    std::vector<std::size_t> covered = coveredShadowTexels(r.shadowMaps());
    std::vector<FrameStats> timed;
    for (int f = 0; f < frames; ++f) timed.push_back(r.render(s));
    r.setOptions(options);
    return summariseCost(timed, covered, s.cascades.mapSize);
}

namespace {
// The cost of `frame`'s settings without timing them: its work with kept maps priced as redrawn.
CostReport countedCost(const FrameStats& frame, const Settings& s) {
    FrameStats counted = frame;
    counted.work = withEveryMapRedrawn(frame);
    CostReport r = summariseCost({counted}, {}, s.cascades.mapSize);
    const double none = std::numeric_limits<double>::quiet_NaN();
    r.frames = 0;
    r.gpuShadowMs = r.gpuMainMs = r.gpuFilterMs = r.cpuMs = none;
    r.gpuShadowRange = r.gpuMainRange = r.gpuFilterRange = r.cpuRange = {none, none};
    for (CascadeCost& c : r.cascades) c.gpuMs = none;
    return r;
}
}  // namespace

std::vector<std::string> frameWarnings(Renderer& r, MeasurePass& pass, const Settings& s, const FrameStats& stats,
                                       const MapWarningLimits& limits) {
    std::vector<std::string> out = zExtensionWarnings(stats);
    const MeasureSamples samples = pass.run(r, s, observerViewProj(s));
    const DensityReport density = texelDensity(samples, s.cascades.count);
    for (std::string& w : wastedMapWarnings(s, stats, density, farthestSampleDepth(samples, r.plan().vsView), limits))
        out.push_back(std::move(w));
    return out;
}

namespace {
// The cached truth of exactly these inputs, moved to the front; traced into a new front entry
// (dropping the least recently used past kCachedViews) when none matches.
MeasureSession::CachedTruth& cachedTruth(MeasureSession::SceneEntry& e, const MeasureSamples& samples, glm::vec3 toSun,
                                         glm::vec3 eye) {
    auto& views = e.views;
    const auto same = [&](const MeasureSession::CachedTruth& c) {
        if (c.toSun != toSun || c.eye != eye) return false;
        if (samples.surface != 0 && c.surface == samples.surface) return true;  // the very surfaces traced
        return c.positions == samples.position && c.normals == samples.normal && c.geometry == samples.geometry;
    };
    if (const auto it = std::find_if(views.begin(), views.end(), same); it != views.end()) {
        std::rotate(views.begin(), it, it + 1);
        if (samples.surface != 0) views.front().surface = samples.surface;
        return views.front();
    }
    MeasureSession::CachedTruth c{samples.position, samples.normal, samples.geometry, toSun, eye,
                                  e.truth->trace(samples, toSun, eye), std::nullopt, {}, {}, samples.surface};
    views.insert(views.begin(), std::move(c));
    if (views.size() > MeasureSession::kCachedViews) views.pop_back();
    return views.front();
}
// The soft truth of `c`'s samples for this disc, traced unless `c` holds it. Returns the
// milliseconds spent.
double cachedSoftTruth(MeasureSession::SceneEntry& e, MeasureSession::CachedTruth& c, const MeasureSamples& samples,
                       const SunDisc& disc) {
    if (c.disc && *c.disc == disc) return 0.0;
    const auto t0 = Clock::now();
    c.soft = e.truth->traceDisc(samples, c.toSun, disc, c.eye);
    c.softRegions = softTruthRegions(samples, c.soft);
    c.disc = disc;
    return msSince(t0);
}

std::vector<float> texelWorldSizes(const csm::CascadePlan& plan) {
    std::vector<float> out;
    for (const csm::CascadeFit& c : plan.cascades) out.push_back(c.texelWorldSize);
    return out;
}
}  // namespace

namespace {
// The renderer's options a measurement asks for, while this lives: MeasureOptions::shadeMain off
// leaves the main pass unshaded; subpixelSteps sets the rasterizer grid drawn with.
class MeasuredOptions {
public:
    MeasuredOptions(Renderer& r, const MeasureOptions& opt) : r_(r), was_(r.options()) {
        RenderOptions o = was_;
        o.shadeMain = was_.shadeMain && opt.shadeMain;
        o.subpixelSteps = opt.subpixelSteps;
        r_.setOptions(o);
    }
    ~MeasuredOptions() { r_.setOptions(was_); }
    MeasuredOptions(const MeasuredOptions&) = delete;
    MeasuredOptions& operator=(const MeasuredOptions&) = delete;

private:
    Renderer& r_;
    RenderOptions was_;
};
}  // namespace

SunDisc sunDisc(const Settings& s) { return {s.light.angularDiameter, s.measure.sunRays, kSunDiscSeed}; }

// Truth, accuracy and texel density of the frame `s` shows: everything but cost and flicker.
void measureStill(MeasureSession::SceneEntry& e, Renderer& r, MeasurePass& pass, const Settings& s, PresetMeasurement& m) {
    auto t0 = Clock::now();
    m.samples = sampleFrame(r, pass, s, s, &m.frame);
    m.timings.measurePassMs = msSince(t0);
    t0 = Clock::now();
    MeasureSession::CachedTruth& cached = cachedTruth(e, m.samples, -r.plan().wsLightDir, s.camera.position);
    m.truth = cached.truth;
    m.timings.groundTruthMs = msSince(t0);
    const ResolutionCheck check(*e.truth, r.plan(), s.cascades.mapSize, s.camera.position);
    m.accuracy = scoreAccuracy(m.samples, m.truth, s.cascades.count, [&](std::size_t i, bool mapLit) {
        return check.explains(glm::vec3(m.samples.position[i]), glm::vec3(m.samples.geometry[i]),
                              m.samples.cascade(i), mapLit);
    });
    m.sun = sunDisc(s);
    m.timings.softTruthMs = cachedSoftTruth(e, cached, m.samples, m.sun);
    m.softTruth = cached.soft;
    m.soft = scoreSoftAccuracy(m.samples, m.softTruth, cached.softRegions, texelWorldSizes(r.plan()),
                               {.k = s.measure.artifactTexels});
    m.density = texelDensity(m.samples, s.cascades.count);
}

void measureStill(MeasureSession::SceneEntry& e, MeasurePass& pass, const Settings& s, PresetMeasurement& m) {
    measureStill(e, *e.renderer, pass, s, m);
}

PresetMeasurement MeasureSession::measure(const Settings& s, const fs::path& presetDir, const MeasureOptions& opt) {
    const auto start = Clock::now();
    PresetMeasurement m;
    m.settings = s;
    SceneEntry& e = entryFor(s, presetDir);
    if (!e.truth) {
        e.truth = std::make_unique<GroundTruth>(*e.scene);
        m.timings.bvhMs = e.truth->buildMs();
    }
    Renderer& r = opt.renderer ? *opt.renderer : *e.renderer;
    {
        const MeasuredOptions options(r, opt);
        measureStill(e, r, pass(), s, m);
    }
    m.warnings = zExtensionWarnings(m.frame);
    const std::optional<float> farthest = farthestSampleDepth(m.samples, r.plan().vsView);
    for (std::string& w : wastedMapWarnings(s, m.frame, m.density, farthest, opt.warningLimits))
        m.warnings.push_back(std::move(w));
    m.frame.warnings = m.warnings;
    report(opt, "ground truth " + seconds(m.timings.groundTruthMs) + " (BVH " + seconds(m.timings.bvhMs) + "), soft truth " +
                    seconds(m.timings.softTruthMs) + " (" + std::to_string(m.sun.rays) + " rays over " +
                    std::to_string(m.sun.angularDiameter).substr(0, 4) + " deg)");
    if (opt.cost) {
        const auto t0 = Clock::now();
        m.cost = opt.costFrames > 0 ? measureCost(r, s, opt.costFrames) : countedCost(m.frame, s);
        if (opt.costProfile) {
            m.cost->model = modelFrame(*opt.costProfile, m.cost->work);
            m.cost->profile = profileName(*opt.costProfile);
        }
        m.timings.costMs = msSince(t0);
    }
    if (opt.flicker && s.path.frames > 0) {
        const auto t0 = Clock::now();
        const MeasuredOptions options(r, opt);
        m.flicker = measureFlicker(r, pass(), s, &m.flickerStdDev, m.truth);
        m.timings.flickerMs = msSince(t0);
        report(opt, "flicker over " + std::to_string(s.path.frames) + " frames " + seconds(m.timings.flickerMs));
    }
    m.timings.totalMs = msSince(start);
    return m;
}

}  // namespace st::metrics
