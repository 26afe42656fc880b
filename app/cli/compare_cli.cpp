// `shadowtune compare`: command-line options of the comparison of two presets.
#include "app/cli/commands.h"
#include "app/cli/number_checks.h"
#include "app/cli/compare_command.h"
#include "app/cli/size_option.h"

#include <cstdio>
#include <memory>
#include <string>

namespace st::app {

void addCompareCommand(CLI::App& cli, int& exitCode) {
    auto opt = std::make_shared<CompareOptions>();
    auto size = std::make_shared<std::string>();
    CLI::App* cmd = cli.add_subcommand(
        "compare", "Measure two presets on the same view; write side-by-side, split and shadow-diff images and deltas");
    cmd->add_option("A", opt->a, "Preset A (its scene, camera, light and output size are used)")->required();
    cmd->add_option("B", opt->b, "Preset B (its cascades, filter and bias are applied onto A's view)")->required();
    cmd->add_option("--out", opt->outDir, "Output folder (created if missing)")->required();
    cmd->add_flag("--keep-b-scene", opt->keepBScene,
                  "Measure B with its own scene, camera, light and path instead of A's");
    cmd->add_option("--size", *size, "Output size of both, WxH (default: A's)");
    cmd->add_option("--frames", opt->costFrames, "Timed frames for the cost figures (after one warm-up)")
        ->check(numberIn(1, 1000))
        ->capture_default_str();
    cmd->add_flag("--debug-gl", opt->debugContext, "Debug context; GL errors fail the comparison");
    cmd->callback([opt, size, &exitCode] {
        if (!size->empty()) {
            const auto wh = parseSize(*size);
            if (!wh) {
                std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", size->c_str());
                exitCode = 2;
                return;
            }
            opt->width = wh->first, opt->height = wh->second;
        }
        exitCode = runCompare(*opt);
    });
}

}  // namespace st::app
