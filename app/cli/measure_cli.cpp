// `shadowtune measure`: command-line options of the measurement command.
#include "app/cli/commands.h"
#include "app/cli/number_checks.h"
#include "app/cli/warning_options.h"
#include "app/cli/measure_command.h"
#include "app/cli/size_option.h"

#include <cstdio>
#include <memory>
#include <string>

namespace st::app {
namespace {

struct MeasureArgs {
    MeasureCommandOptions opt;
    std::string size;
    bool noFlicker = false;
};

bool applySize(MeasureArgs& a) {
    if (a.size.empty()) return true;
    const auto size = parseSize(a.size);
    if (!size) {
        std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", a.size.c_str());
        return false;
    }
    a.opt.width = size->first;
    a.opt.height = size->second;
    return true;
}

}  // namespace

void addMeasureCommand(CLI::App& cli, int& exitCode) {
    auto args = std::make_shared<MeasureArgs>();
    CLI::App* cmd = cli.add_subcommand(
        "measure", "Measure presets against ray-cast ground truth: accuracy, texel density, flicker, cost");
    cmd->add_option("presets", args->opt.presets, "Preset JSON files")->required();
    cmd->add_option("--out", args->opt.outDir, "Output folder; each preset gets OUT/<name>/")->capture_default_str();
    cmd->add_option("--size", args->size, "Override the output size, WxH (e.g. 1280x720)");
    cmd->add_option("--frames", args->opt.costFrames, "Timed frames for the cost figures (after one warm-up)")
        ->check(numberIn(1, 1000))
        ->capture_default_str();
    cmd->add_option("--profile", args->opt.costProfile,
                    "Cost profile of the modelled cost (default: the shipped llvmpipe profile)");
    cmd->add_flag("--no-flicker", args->noFlicker, "Skip replaying the presets' camera paths");
    cmd->add_flag("--debug-gl", args->opt.debugContext, "Debug context; GL errors fail the preset");
    addWarningOptions(*cmd, args->opt.warningLimits);
    cmd->callback([args, &exitCode] {
        args->opt.flicker = !args->noFlicker;
        exitCode = applySize(*args) ? runMeasure(args->opt) : 2;
    });
}

}  // namespace st::app
