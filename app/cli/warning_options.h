#pragma once
// --warn-texel and --warn-pixels-per-texel of `render` and `measure`: the stated limits of the
// wasted-map warnings (metrics/map_warnings.h).
#include "metrics/map_warnings.h"

#include <CLI/CLI.hpp>

namespace st::app {

void addWarningOptions(CLI::App& cmd, metrics::MapWarningLimits& limits);

}  // namespace st::app
