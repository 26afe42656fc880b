#pragma once
// Accuracy of the shadow-map test against the ground truth (docs/architecture.md#misclassification,
// #filtered-error). The denominator is the receivers: pixels with a surface that faces the sun
// (MeasureSamples::receiver). Pixels facing away are shadowed in truth and in the image
// whatever the map says (the main pass multiplies by max(N.L, 0)); terminator pixels (smooth
// normal toward the sun, triangle away from it) have no answer the map could get right. Both
// are counted apart and scored nowhere.
#include "metrics/parallel_rows.h"
#include "renderer/render/measure_samples.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace st::metrics {

// How one pixel fares. Edge: within the local texel footprint of a true shadow edge, where a
// map of finite resolution must err (expected aliasing; resolution_check.h says how that is
// decided). Gross: anything else (acne, leaks, missing casters, seams).
enum class PixelClass : std::uint8_t {
    NoSurface,
    FacingAway,
    Terminator,
    CorrectLit,
    CorrectShadow,
    FalseShadowEdge,   // map says shadow, truth says lit (acne-like), near a true edge
    FalseShadowGross,
    FalseLightEdge,    // map says lit, truth says shadow (missing caster, peter-panning)
    FalseLightGross,
};

struct ErrorCounts {
    std::size_t receivers = 0;
    std::size_t falseShadowEdge = 0;
    std::size_t falseShadowGross = 0;
    std::size_t falseLightEdge = 0;
    std::size_t falseLightGross = 0;
    double filteredAbsErrorSum = 0.0;  // sum of |filtered factor - truth|

    void add(PixelClass c, double filteredAbsError);
    std::size_t falseShadow() const { return falseShadowEdge + falseShadowGross; }
    std::size_t falseLight() const { return falseLightEdge + falseLightGross; }
    std::size_t misclassified() const { return falseShadow() + falseLight(); }
    std::size_t gross() const { return falseShadowGross + falseLightGross; }
    double share(std::size_t count) const { return receivers ? double(count) / double(receivers) : 0.0; }
    double filteredError() const { return receivers ? filteredAbsErrorSum / double(receivers) : 0.0; }
};

struct AccuracyReport {
    ErrorCounts all;
    std::vector<ErrorCounts> cascades;  // by the cascade the pixel selected
    ErrorCounts beyond;                 // past the shadow range: the renderer draws them lit
    std::size_t covered = 0;            // pixels with a surface
    std::size_t facingAway = 0;
    std::size_t terminator = 0;
    std::size_t edgePixels = 0;         // pixels on a true lit/shadow boundary
    std::vector<PixelClass> classes;    // per pixel, for the error map
};

// Pixels on a true shadow boundary: a surface pixel whose 4-neighbour has a surface and the
// other truth value (facing-away pixels count as shadowed, so terminators are edges too).
std::vector<std::uint8_t> truthEdges(const MeasureSamples& samples, const std::vector<std::uint8_t>& truth);

// Whether the map's resolution explains the error at `pixel`, whose unfiltered test said
// `mapLit` (ResolutionCheck::explains for the production code).
using ResolutionExplains = std::function<bool(std::size_t pixel, bool mapLit)>;

// Scores the unfiltered test (samples.shadow.x) and the filtered factor (.y) against `truth`
// (1 lit, 0 shadowed) over `cascadeCount` cascades. Errors beyond the shadow range are gross
// (a missing shadow that no resolution would bring back). Pixels are classified on the cores
// `control` allows (`explains` casts rays); a cancelled report is incomplete, for throwing away.
AccuracyReport scoreAccuracy(const MeasureSamples& samples, const std::vector<std::uint8_t>& truth, int cascadeCount,
                             const ResolutionExplains& explains, const RowControl& control = {});

}  // namespace st::metrics
