#include "metrics/still_accuracy.h"

#include "metrics/metric_images.h"
#include "metrics/resolution_check.h"

#include <chrono>

namespace st::metrics {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// The part of measureStill after the read-back, rows under `control`.
AccuracyReport score(const StillFrame& f, const GroundTruth& truth, const std::vector<std::uint8_t>& lit,
                     JobControl& control) {
    const ResolutionCheck check(truth, f.plan, f.mapSize, f.wsEye);
    const MeasureSamples& s = f.samples;
    const auto explains = [&](std::size_t i, bool mapLit) {
        return check.explains(glm::vec3(s.position[i]), glm::vec3(s.geometry[i]), s.cascade(i), mapLit);
    };
    return scoreAccuracy(s, lit, f.cascadeCount, explains, control.rows());
}

}  // namespace

const GroundTruth& GroundTruthCache::get(const std::shared_ptr<const Scene>& scene, bool* built) {
    if (built) *built = false;
    if (truth_ && scene_ == scene) return *truth_;
    truth_.reset();  // the old BVH refers to the old scene: drop it first
    scene_ = scene;
    truth_ = std::make_unique<GroundTruth>(*scene_);
    if (built) *built = true;
    return *truth_;
}

std::optional<StillAccuracy> computeStillAccuracy(const StillFrame& f, GroundTruthCache& cache, JobControl& control) {
    StillAccuracy out;
    if (control.cancelled()) return std::nullopt;
    control.phase = JobControl::Phase::Bvh;
    bool built = false;
    const GroundTruth& truth = cache.get(f.scene, &built);
    if (built) out.bvhMs = truth.buildMs();

    control.phase = JobControl::Phase::Rays;
    auto t0 = Clock::now();
    const std::vector<std::uint8_t> lit = truth.trace(f.samples, -f.plan.wsLightDir, f.wsEye, {}, control.rows());
    out.raysMs = msSince(t0);
    if (control.cancelled()) return std::nullopt;

    t0 = Clock::now();
    const SoftTruth soft = truth.traceDisc(f.samples, -f.plan.wsLightDir, f.sun, f.wsEye, {}, control.rows());
    out.softRaysMs = msSince(t0);
    if (control.cancelled()) return std::nullopt;

    control.phase = JobControl::Phase::Scoring;
    t0 = Clock::now();
    out.report = score(f, truth, lit, control);
    if (control.cancelled()) return std::nullopt;
    std::vector<float> texels;
    for (const csm::CascadeFit& c : f.plan.cascades) texels.push_back(c.texelWorldSize);
    out.soft = scoreSoftAccuracy(f.samples, soft, texels, {.k = f.artifactTexels});
    out.overlay = errorOverlayImage(out.report, f.samples.width, f.samples.height);
    out.scoreMs = msSince(t0);
    return out;
}

}  // namespace st::metrics
