#include "app/cli/warning_options.h"
#include "app/cli/number_checks.h"

namespace st::app {

void addWarningOptions(CLI::App& cmd, metrics::MapWarningLimits& limits) {
    cmd.add_option("--warn-texel", limits.maxTexelMetres,
                   "Warn (stderr) about a cascade showing pixels whose texel is larger than this, metres")
        ->check(positiveNumber())
        ->capture_default_str();
    cmd.add_option("--warn-pixels-per-texel", limits.maxPixelsPerTexel,
                   "Warn (stderr) about a cascade whose median screen pixels per shadow texel is above this")
        ->check(positiveNumber())
        ->capture_default_str();
}

}  // namespace st::app
