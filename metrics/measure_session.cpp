#include "metrics/measure_session.h"

#include "metrics/camera_path.h"
#include "metrics/map_warnings.h"
#include "metrics/resolution_check.h"
#include "renderer/csm/cascade_plan.h"

#include <chrono>
#include <cstdio>

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
    FlickerMeter meter(first, truth);
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
// The truth of `samples`, traced unless the entry's last frame had exactly these inputs.
std::vector<std::uint8_t> cachedTruth(MeasureSession::SceneEntry& e, const MeasureSamples& samples, glm::vec3 toSun,
                                      glm::vec3 eye) {
    const bool same = !e.lastTruth.empty() && e.lastToSun == toSun && e.lastEye == eye &&
                      e.lastPositions == samples.position && e.lastNormals == samples.normal &&
                      e.lastGeometry == samples.geometry;
    if (!same) {
        e.lastDisc.reset();  // the soft truth was of other samples
        e.lastTruth = e.truth->trace(samples, toSun, eye);
        e.lastPositions = samples.position;
        e.lastNormals = samples.normal;
        e.lastGeometry = samples.geometry;
        e.lastToSun = toSun;
        e.lastEye = eye;
    }
    return e.lastTruth;
}
// The soft truth of `samples` (cachedTruth() must have run on them just before: it keeps the
// entry's inputs), traced unless the entry holds it for this disc. Returns the milliseconds spent.
double cachedSoftTruth(MeasureSession::SceneEntry& e, const MeasureSamples& samples, const SunDisc& disc) {
    if (e.lastDisc && *e.lastDisc == disc) return 0.0;
    const auto t0 = Clock::now();
    e.lastSoft = e.truth->traceDisc(samples, e.lastToSun, disc, e.lastEye);
    e.lastDisc = disc;
    return msSince(t0);
}

std::vector<float> texelWorldSizes(const csm::CascadePlan& plan) {
    std::vector<float> out;
    for (const csm::CascadeFit& c : plan.cascades) out.push_back(c.texelWorldSize);
    return out;
}
}  // namespace

SunDisc sunDisc(const Settings& s) { return {s.light.angularDiameter, s.measure.sunRays, kSunDiscSeed}; }

// Truth, accuracy and texel density of the frame `s` shows: everything but cost and flicker.
void measureStill(MeasureSession::SceneEntry& e, MeasurePass& pass, const Settings& s, PresetMeasurement& m) {
    auto t0 = Clock::now();
    m.samples = sampleFrame(*e.renderer, pass, s, s, &m.frame);
    m.timings.measurePassMs = msSince(t0);
    t0 = Clock::now();
    m.truth = cachedTruth(e, m.samples, -e.renderer->plan().wsLightDir, s.camera.position);
    m.timings.groundTruthMs = msSince(t0);
    const ResolutionCheck check(*e.truth, e.renderer->plan(), s.cascades.mapSize, s.camera.position);
    m.accuracy = scoreAccuracy(m.samples, m.truth, s.cascades.count, [&](std::size_t i, bool mapLit) {
        return check.explains(glm::vec3(m.samples.position[i]), glm::vec3(m.samples.geometry[i]),
                              m.samples.cascade(i), mapLit);
    });
    m.sun = sunDisc(s);
    m.timings.softTruthMs = cachedSoftTruth(e, m.samples, m.sun);
    m.softTruth = e.lastSoft;
    m.soft = scoreSoftAccuracy(m.samples, m.softTruth, texelWorldSizes(e.renderer->plan()),
                               {.k = s.measure.artifactTexels});
    m.density = texelDensity(m.samples, s.cascades.count);
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
    measureStill(e, pass(), s, m);
    m.warnings = zExtensionWarnings(m.frame);
    const std::optional<float> farthest = farthestSampleDepth(m.samples, e.renderer->plan().vsView);
    for (std::string& w : wastedMapWarnings(s, m.frame, m.density, farthest, opt.warningLimits))
        m.warnings.push_back(std::move(w));
    m.frame.warnings = m.warnings;
    report(opt, "ground truth " + seconds(m.timings.groundTruthMs) + " (BVH " + seconds(m.timings.bvhMs) + "), soft truth " +
                    seconds(m.timings.softTruthMs) + " (" + std::to_string(m.sun.rays) + " rays over " +
                    std::to_string(m.sun.angularDiameter).substr(0, 4) + " deg)");
    if (opt.cost) {
        const auto t0 = Clock::now();
        m.cost = measureCost(*e.renderer, s, opt.costFrames);
        if (opt.costProfile) {
            m.cost->model = modelFrame(*opt.costProfile, m.cost->work);
            m.cost->profile = profileName(*opt.costProfile);
        }
        m.timings.costMs = msSince(t0);
    }
    if (opt.flicker && s.path.frames > 0) {
        const auto t0 = Clock::now();
        m.flicker = measureFlicker(*e.renderer, pass(), s, &m.flickerStdDev, m.truth);
        m.timings.flickerMs = msSince(t0);
        report(opt, "flicker over " + std::to_string(s.path.frames) + " frames " + seconds(m.timings.flickerMs));
    }
    m.timings.totalMs = msSince(start);
    return m;
}

}  // namespace st::metrics
