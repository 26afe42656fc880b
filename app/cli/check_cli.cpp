// `shadowtune check`: command-line options of the golden check.
#include "app/cli/check_command.h"
#include "app/cli/commands.h"

#include <memory>

namespace st::app {

void addCheckCommand(CLI::App& cli, int& exitCode) {
    auto opt = std::make_shared<CheckCommandOptions>();
    CLI::App* cmd = cli.add_subcommand(
        "check", "Replay a suite of presets headless and compare images and accuracy figures with reviewed goldens");
    cmd->add_option("suite", opt->suite, "Suite JSON file (schema/suite.schema.json)")->required();
    cmd->add_option("--golden", opt->golden, "Golden folder: <preset>/ or <renderer-slug>/<preset>/")->required();
    cmd->add_flag("--update", opt->update, "Write the goldens from this run (atomically) and print what changed");
    cmd->add_option("--report", opt->reportDir, "Write index.html, results.json and the images into this folder");
    cmd->add_option("--junit", opt->junit, "Write JUnit XML to this file");
    cmd->add_option("--only", opt->only, "Check only presets whose name matches this glob (e.g. 'xna-*')");
    cmd->callback([opt, &exitCode] { exitCode = runCheck(*opt); });
}

}  // namespace st::app
