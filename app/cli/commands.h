#pragma once
// Each command registers its own subcommand; its callback stores the process exit code.
#include <CLI/CLI.hpp>

namespace st::app {

void addRenderCommand(CLI::App& cli, int& exitCode);
void addEditorCommand(CLI::App& cli, int& exitCode);
void addMeasureCommand(CLI::App& cli, int& exitCode);
void addSweepCommand(CLI::App& cli, int& exitCode);
void addCompareCommand(CLI::App& cli, int& exitCode);
void addExportCommand(CLI::App& cli, int& exitCode);
void addCalibrateCommand(CLI::App& cli, int& exitCode);
void addTuneCommand(CLI::App& cli, int& exitCode);
void addCheckCommand(CLI::App& cli, int& exitCode);
void addEngineCheckCommand(CLI::App& cli, int& exitCode);
void addInitCommand(CLI::App& cli, int& exitCode);

}  // namespace st::app
