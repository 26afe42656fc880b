#pragma once
#include "metrics/map_warnings.h"
#include "renderer/settings/settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

struct RenderOptions {
    std::vector<std::filesystem::path> presets;
    std::filesystem::path outDir = "out";
    std::optional<View> view;        // overrides every preset's view
    std::optional<int> width, height; // overrides every preset's output size
#ifdef NDEBUG
    bool debugContext = false;       // KHR_debug; any serious message fails the preset
#else
    bool debugContext = true;        // always on in debug builds: GL errors are bugs
#endif
    std::filesystem::path costProfile;  // --profile; empty: the shipped llvmpipe profile
    int frames = 1;                  // > 1: render repeatedly and report median times
    metrics::MapWarningLimits warningLimits;  // when a cascade's map counts as wasted (stderr)
};

// Renders each preset to OUT/<name>.png and OUT/<name>.json, one line per image on stdout.
// A failing preset is reported on stderr and skipped. Returns the process exit code.
int runRender(const RenderOptions& opt);

}  // namespace st::app
