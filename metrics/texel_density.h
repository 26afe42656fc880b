#pragma once
// Texel density (docs/architecture.md#texel-density): screen pixels covered by one shadow
// texel at each pixel, 1 / |det d(texel)/d(screen)| (shadow_sampling.glsl, the same formula the
// texel-density view colours). 1 is ideal; above 1 one texel is smeared over several pixels
// (perspective aliasing); below 1/4 the map spends four or more texels per pixel (wasted).
#include "renderer/render/measure_samples.h"

#include <cstddef>
#include <vector>

namespace st::metrics {

inline constexpr double kAliasingAbove = 1.0;
inline constexpr double kWastedBelow = 0.25;

struct DensityStats {
    std::size_t pixels = 0;  // surface pixels inside the shadow range
    double median = 0.0;
    double p90 = 0.0;
    double p95 = 0.0;
    double max = 0.0;
    double aliasingShare = 0.0;  // share of pixels above kAliasingAbove
    double wastedShare = 0.0;    // share of pixels below kWastedBelow
};

struct DensityReport {
    DensityStats all;
    std::vector<DensityStats> cascades;  // by the cascade each pixel selected
};

// Nearest-rank quantiles: the value at rank ceil(q n) of the sorted values.
DensityStats densityStats(std::vector<float> values);

DensityReport texelDensity(const MeasureSamples& samples, int cascadeCount);

}  // namespace st::metrics
