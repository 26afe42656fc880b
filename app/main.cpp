// shadowtune: entry point. Each command lives in its own file and registers itself here.
#include "app/cli/commands.h"
#include "app/version.h"
#include "report/chart_fonts.h"

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
    CLI11_PARSE(cli, argc, argv);
    return exitCode;
}
