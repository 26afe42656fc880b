// `shadowtune export PRESET --to ENGINE [--json]`: a preset's nearest settings in another
// engine's terms (renderer/export/engine_export.h). Needs no GL context.
#include "app/cli/commands.h"

#include "renderer/export/engine_export.h"
#include "renderer/settings/settings_json.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

namespace st::app {
namespace {

struct ExportArgs {
    std::string preset;
    std::string engine;
    bool json = false;
};

int runExport(const ExportArgs& a) {
    const std::optional<xport::Engine> engine = xport::parseEngine(a.engine);
    if (!engine) {
        std::fprintf(stderr, "error: --to: unknown engine '%s'; expected one of: %s\n", a.engine.c_str(),
                     xport::engineList().c_str());
        return 2;
    }
    try {
        const xport::EngineExport e = xport::exportSettings(loadPreset(a.preset), *engine);
        const std::string out = a.json ? xport::toJson(e).dump(2) + "\n" : xport::toText(e);
        std::fputs(out.c_str(), stdout);
        return 0;
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "error: %s\n", ex.what());
        return 1;
    }
}

}  // namespace

void addExportCommand(CLI::App& cli, int& exitCode) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App* cmd = cli.add_subcommand("export", "Print a preset's nearest shadow settings in another engine's terms");
    cmd->add_option("preset", args->preset, "Preset JSON file")->required();
    cmd->add_option("--to", args->engine, "Engine: " + xport::engineList())->required();
    cmd->add_flag("--json", args->json, "Print JSON: engine, title, exact, approximated, noEquivalent");
    cmd->callback([args, &exitCode] { exitCode = runExport(*args); });
}

}  // namespace st::app
