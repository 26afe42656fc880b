#pragma once
// Cost (docs/architecture.md#cost): GPU time per pass (timer queries, median with minimum and
// maximum over forced-redraw frames after a warm-up), CPU time, the counted work per pass (identical
// in every timed frame: renderer/render/pass_work.h), shadow-map memory, caster triangles and draw calls submitted per cascade,
// and texels: every layer's mapSize^2 is cleared and rasterised into, of which casters cover
// `texelsCovered`.
#include "metrics/cost_model.h"
#include "renderer/render/frame_stats.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace st::metrics {

struct CascadeCost {
    int draws = 0;
    std::size_t triangles = 0;
    double gpuMs = 0.0;  // median
    std::size_t texels = 0;         // its mapSize^2
    std::size_t texelsCovered = 0;  // depth written below the clear value
};

// Minimum and maximum over the timed frames, beside CostReport's medians.
struct TimeRange {
    double minMs = 0.0;
    double maxMs = 0.0;
    bool operator==(const TimeRange&) const = default;
};

struct CostReport {
    int frames = 0;           // timed frames (after the warm-up frame)
    double gpuShadowMs = 0.0; // medians
    double gpuMainMs = 0.0;
    double gpuFilterMs = 0.0; // the filter's extra passes (moment maps and their blur, the screen-space path)
    double cpuMs = 0.0;
    TimeRange gpuShadowRange;
    TimeRange gpuMainRange;
    TimeRange gpuFilterRange;
    TimeRange cpuRange;
    FrameWork work;           // of every timed frame (summariseCost checks they agree)
    std::size_t shadowMapBytes = 0;
    std::size_t filterMapBytes = 0;  // the filter's own maps
    std::size_t sceneTriangles = 0;
    std::size_t texels = 0;
    std::size_t texelsCovered = 0;
    int draws = 0;
    std::size_t triangles = 0;  // caster triangles over all cascades
    std::vector<CascadeCost> cascades;
    // The cost model's figure for `work` (metrics/cost_model.h): the same in every run of the same
    // settings, unlike the timers. Absent without a profile; `profile` names the one used.
    std::optional<ModelledCost> model;
    std::string profile;
};

double median(std::vector<double> values);  // 0 for none; the upper median for an even count

// `frames`: the timed frames' statistics (not the warm-up), all of the same settings; throws
// std::logic_error when their counted work differs (it must not for the same settings).
// `covered`: texels written per cascade (coveredShadowTexels); each cascade has its stats' mapSize
// texels per side (`mapSize` when the stats carry none).
CostReport summariseCost(const std::vector<FrameStats>& frames, const std::vector<std::size_t>& covered, int mapSize);

}  // namespace st::metrics
