#pragma once
// Warnings that a frame wastes its shadow maps or cuts casters off, each with the likely fix:
// what `render`, `measure` and the editor print. Pure: figures in, lines of text out.
#include "metrics/texel_density.h"
#include "renderer/render/frame_stats.h"
#include "renderer/render/measure_samples.h"
#include "renderer/settings/settings.h"

#include <glm/mat4x4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace st::metrics {

struct MapWarningLimits {
    float maxTexelMetres = 1.0f;     // a cascade that shows pixels with texels larger than this
    double maxPixelsPerTexel = 4.0;  // a cascade whose median screen pixels per texel is above this
};

// Farthest view depth of the covered samples (`vsView`: the cascade camera's view matrix);
// nullopt when none is covered. What the fix for a too-long split range quotes.
std::optional<float> farthestSampleDepth(const MeasureSamples& samples, const glm::mat4& vsView);

// Per cascade that shows pixels (density.cascades[i].pixels > 0): texel above the limit, or
// median pixels per texel above it, e.g.
// "cascade 0: median 22 screen pixels per shadow texel (limit 4); likely fix: cascades.depthBounds
//  "fit" or cascades.shadowDistance 310 m (the splits run to 1500 m, the farthest surface seen is at 310 m)".
std::vector<std::string> wastedMapWarnings(const Settings& s, const FrameStats& stats, const DensityReport& density,
                                           std::optional<float> farthestSeen, const MapWarningLimits& limits = {});

// The z-extension audit's cascades that cut casters (renderer/csm/z_extension_audit.h).
std::vector<std::string> zExtensionWarnings(const FrameStats& stats);

}  // namespace st::metrics
