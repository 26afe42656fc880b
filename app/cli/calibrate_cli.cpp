// `shadowtune calibrate`: command-line options of the cost-model calibration.
#include "app/cli/calibrate_command.h"
#include "app/cli/number_checks.h"
#include "app/cli/commands.h"
#include "app/cli/size_option.h"
#include "metrics/cost_model.h"

#include <cstdio>
#include <memory>
#include <string>

namespace st::app {

void addCalibrateCommand(CLI::App& cli, int& exitCode) {
    auto opt = std::make_shared<CalibrateOptions>();
    auto size = std::make_shared<std::string>();
    CLI::App* cmd = cli.add_subcommand(
        "calibrate", "Fit the cost model on this machine: time a fixed set of presets and write the cost profile");
    cmd->add_option("--out", opt->out, "Profile JSON to write")->capture_default_str();
    cmd->add_option("--frames", opt->frames, "Timed frames per preset (after one untimed frame)")
        ->check(numberIn(1, 1000))
        ->capture_default_str();
    cmd->add_option("--size", *size, "Override every preset's output size, WxH");
    cmd->add_option("--sweeps", opt->sweeps,
                    "Sweeps whose points join the calibration set, every 7th from the 4th (default: the shipped "
                    "presets/sweeps/*.json); calibrate on the scenes you tune");
    cmd->add_option("--check", opt->check,
                    "Instead of calibrating, time these sweeps' points and compare them with --profile's modelled cost");
    cmd->add_option("--every", opt->every, "With --check: every k-th point of each sweep")
        ->check(numberIn(1, 100000))
        ->capture_default_str();
    cmd->add_option("--passes", opt->passes,
                    "Time every point this many times, in passes over all of them, and join their frames (the "
                    "machine's speed drifts over minutes)")
        ->check(numberIn(1, 20))
        ->capture_default_str();
    cmd->add_option("--profile", opt->profile,
                    "With --check or --refit: the profile (default: the shipped llvmpipe profile)");
    cmd->add_option("--refit", opt->refit,
                    "Refit only this pass kind on its own timers (depthBounds), keeping --profile's other "
                    "coefficients; times only the calibration points that run it")
        ->check([](const std::string& kind) -> std::string {
            const auto k = metrics::passKindFromName(kind);
            if (!k) return "unknown pass kind '" + kind + "' (expected depthBounds)";
            if (!metrics::fittedOnOwnTimers(*k))
                return "the " + kind + " pass is fitted jointly on frame totals, not alone; run calibrate without --refit";
            return "";
        });
    cmd->add_option("--samples", opt->samples,
                    "Also write every timed point's counted work and frame times here (JSON lines)");
    cmd->add_flag("--debug-gl", opt->debugContext, "Debug context; GL errors fail the run");
    cmd->callback([opt, size, &exitCode] {
        if (!size->empty()) {
            opt->size = parseSize(*size);
            if (!opt->size) {
                std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", size->c_str());
                exitCode = 2;
                return;
            }
        }
        if (!opt->refit.empty() && !opt->check.empty()) {
            std::fprintf(stderr, "error: --refit and --check: choose one\n");
            exitCode = 2;
            return;
        }
        exitCode = runCalibrate(*opt);
    });
}

}  // namespace st::app
