// shadowtune: entry point. Each command lives in its own file and registers itself here.
#include "app/cli/commands.h"
#include "app/version.h"
#include "report/chart_fonts.h"

#include <cstdio>

int main(int argc, char** argv) {
    st::report::nameChartFonts();  // sets the environment: before any thread starts
    CLI::App cli{"shadowtune: tune cascaded shadow maps"};
    cli.require_subcommand(1);
    cli.set_version_flag("--version", st::app::versionText(), "Print the version and git commit, then exit");
    int exitCode = 0;
    st::app::addRenderCommand(cli, exitCode);
    st::app::addEditorCommand(cli, exitCode);
    st::app::addMeasureCommand(cli, exitCode);
    st::app::addSweepCommand(cli, exitCode);
    st::app::addCompareCommand(cli, exitCode);
    st::app::addExportCommand(cli, exitCode);
    st::app::addCalibrateCommand(cli, exitCode);
    st::app::addTuneCommand(cli, exitCode);
    st::app::addCheckCommand(cli, exitCode);
    st::app::addEngineCheckCommand(cli, exitCode);
    st::app::addInitCommand(cli, exitCode);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        // A usage error: one line naming the option, its value and what it allows, exit 2, and no
        // command has run (CLI11 validates every option before it calls a command).
        std::fprintf(stderr, "error: %s (shadowtune %s--help lists the options)\n", e.what(),
                     cli.get_subcommands().empty() ? "" : (cli.get_subcommands().front()->get_name() + " ").c_str());
        return 2;
    }
    return exitCode;
}
