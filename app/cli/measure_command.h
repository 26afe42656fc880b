#pragma once
#include "metrics/map_warnings.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace st::app {

struct MeasureCommandOptions {
    std::vector<std::filesystem::path> presets;
    std::filesystem::path outDir = "measure";
    std::optional<int> width, height;  // override every preset's output size
    int costFrames = 5;                // timed frames for the cost figures, after a warm-up
    std::filesystem::path costProfile; // --profile; empty: the shipped llvmpipe profile
    bool flicker = true;               // replay each preset's camera path
    metrics::MapWarningLimits warningLimits;  // when a cascade's map counts as wasted (stderr)
#ifdef NDEBUG
    bool debugContext = false;         // KHR_debug; any serious message fails the preset
#else
    bool debugContext = true;
#endif
};

// Measures each preset into OUT/<stem>/metrics.json and images (truth.png, errors.png,
// texel-density.png, flicker.png with a path), printing progress and one summary line per
// preset. A failing preset is reported on stderr and skipped. Returns the process exit code.
int runMeasure(const MeasureCommandOptions& opt);

}  // namespace st::app
