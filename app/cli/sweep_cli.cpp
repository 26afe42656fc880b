// `shadowtune sweep`: command-line options of the sweep command.
#include "app/cli/commands.h"
#include "app/cli/number_checks.h"
#include "app/cli/sweep_command.h"
#include "sweep/sweep_results.h"

#include <memory>

namespace st::app {

void addSweepCommand(CLI::App& cli, int& exitCode) {
    auto opt = std::make_shared<SweepCommandOptions>();
    CLI::App* cmd = cli.add_subcommand(
        "sweep", "Measure every combination of a sweep file's axes in one process; chart error against cost");
    cmd->add_option("sweep", opt->sweepFile, "Sweep file (JSON, see presets/sweeps/)");
    cmd->add_option("--out", opt->outDir, "Output folder (results, charts, front presets); rerun to resume")->required();
    cmd->add_option("--shard", opt->shard, "k/n: measure only every n-th point starting at the k-th (k = 1..n)");
    cmd->add_option("--merge", opt->merge, "Join these shard folders of one sweep into --out instead of measuring")
        ->expected(1, -1);
    cmd->add_option("--error", opt->error, "Error figure of the charts and the front")
        ->check(CLI::IsMember(sweep::errorChoices()))
        ->capture_default_str();
    cmd->add_option("--cost", opt->cost, "Cost figure of the Pareto chart and the front (model: the cost model's ms, repeatable; measured: GPU timers; memory: map bytes)")
        ->check(CLI::IsMember(sweep::costChoices()))
        ->capture_default_str();
    cmd->add_option("--profile", opt->costProfile,
                    "Cost profile of the modelled cost (default: the shipped llvmpipe profile; `shadowtune calibrate` writes one)");
    cmd->add_option("--stop-after", opt->stopAfter, "Measure at most N new points, then stop as Ctrl-C would")
        ->check(nonNegativeNumber());
    cmd->add_option("--frames", opt->costFrames, "Timed frames per point for the cost figures (after one warm-up)")
        ->check(numberIn(1, 1000))
        ->capture_default_str();
    cmd->add_flag("--debug-gl", opt->debugGl, "Debug GL context; a medium/high KHR_debug message fails the sweep");
    cmd->callback([opt, &exitCode] { exitCode = runSweepCommand(*opt); });
}

}  // namespace st::app
