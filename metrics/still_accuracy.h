#pragma once
// The accuracy of one still frame computed away from the GL thread, for the editor's Accuracy
// panel: the same ground truth and scoring as MeasureSession's measureStill, from samples the
// caller read back on its GL thread, with a cancel flag and progress the UI can watch.
#include "metrics/accuracy.h"
#include "metrics/ground_truth.h"
#include "metrics/soft_accuracy.h"
#include "renderer/csm/cascade_plan.h"
#include "renderer/image/image_io.h"
#include "renderer/render/measure_samples.h"
#include "renderer/scene/scene.h"

#include <glm/vec3.hpp>

#include <atomic>
#include <memory>
#include <optional>

namespace st::metrics {

// Everything the job needs, copied off the GL thread. The scene is shared so that it outlives
// the BVH built over it even if the editor loads another one meanwhile.
struct StillFrame {
    std::shared_ptr<const Scene> scene;
    MeasureSamples samples;  // MeasurePass::run of the frame
    csm::CascadePlan plan;   // the cascades that frame was rendered with
    int mapSize = 0;
    int cascadeCount = 0;
    glm::vec3 wsEye{0.0f};
    SunDisc sun;                  // sunDisc() of the settings (light.angularDiameter, measure.sunRays)
    float artifactTexels = 2.0f;  // measure.artifactTexels
};

struct StillAccuracy {
    AccuracyReport report;
    SoftAccuracyReport soft;  // the filtered result against the sun's disc
    Rgba8Image overlay;  // errorOverlayImage of the report, samples' size
    double bvhMs = 0.0;  // 0 when the BVH of the scene was already built
    double raysMs = 0.0;
    double softRaysMs = 0.0;  // the sun's disc
    double scoreMs = 0.0;
};

// Shared between the job and whoever watches it. Progress counts rows: each row is traced once,
// traced twice over the sun's disc and scored once, so a job is done at 4 * height.
struct JobControl {
    enum class Phase { Queued, Bvh, Rays, Scoring };
    std::atomic<bool> cancel{false};
    std::atomic<int> rowsDone{0};
    std::atomic<Phase> phase{Phase::Queued};
    unsigned threads = 0;  // rows run on this many threads; 0: one per core

    RowControl rows() { return {&cancel, &rowsDone, threads}; }
    bool cancelled() const { return cancel.load(std::memory_order_relaxed); }
};

// The BVH of the last scene asked for. Building one is the slow start of a job on a big scene,
// so it is kept while the scene stays the same. Not thread-safe: one per worker thread.
class GroundTruthCache {
public:
    // The truth for `scene`, building it if needed; `built` says whether that happened.
    const GroundTruth& get(const std::shared_ptr<const Scene>& scene, bool* built = nullptr);

private:
    std::shared_ptr<const Scene> scene_;  // keeps the scene alive while truth_ refers to it
    std::unique_ptr<GroundTruth> truth_;
};

// Traces and scores `frame`. Returns nothing if control.cancel was set before it finished.
// Throws std::runtime_error if Embree fails.
std::optional<StillAccuracy> computeStillAccuracy(const StillFrame& frame, GroundTruthCache& cache, JobControl& control);

}  // namespace st::metrics
