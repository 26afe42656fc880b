#include "app/cli/warning_options.h"

namespace st::app {

void addWarningOptions(CLI::App& cmd, metrics::MapWarningLimits& limits) {
    cmd.add_option("--warn-texel", limits.maxTexelMetres,
                   "Warn (stderr) about a cascade showing pixels whose texel is larger than this, metres")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd.add_option("--warn-pixels-per-texel", limits.maxPixelsPerTexel,
                   "Warn (stderr) about a cascade whose median screen pixels per shadow texel is above this")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
}

}  // namespace st::app
