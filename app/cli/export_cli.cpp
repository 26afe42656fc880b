// `shadowtune export PRESET --to ENGINE [--json] [--paste DIR]`: a preset's nearest settings in another
// engine's terms (renderer/export/engine_export.h), and, for an engine with a knob table, the knobs
// its table takes for them, what it lacks and the paste-ready text (engine_knobs.h,
// engine_snippets.h: the same the tuner and the editor write). Needs no GL context.
#include "app/cli/commands.h"

#include "renderer/export/engine_export.h"
#include "renderer/export/engine_knobs.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"

#include <filesystem>

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
    std::string paste;  // a folder for ENGINE.json and the paste-ready text
};

// The knob table's part: its knobs for the preset and what the engine lacks of it.
std::string knobsText(xport::Engine e, const xport::EngineKnobs& k) {
    std::string out = "\nknobs (" + xport::engineName(e) + "'s knob table: what `tune --engine " + xport::engineName(e) +
                      "` and the editor's Engine section use):\n";
    for (auto it = k.knobs.begin(); it != k.knobs.end(); ++it) {
        const std::string unit = xport::knobUnit(e, it.key());
        out += "  " + it.key() + " = " + it.value().dump() + (unit.empty() ? "" : " (" + unit + ")") + "\n";
    }
    out += k.lacks.empty() ? "lacks: nothing: the engine takes these settings whole\n" : "lacks:\n";
    for (const std::string& l : k.lacks) out += "  " + l + "\n";
    return out;
}

void writePaste(xport::Engine e, const xport::EngineKnobs& k, const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    const std::string name = xport::engineName(e);
    writeTextAtomic(dir / (name + ".json"), nlohmann::json{{"engine", name}, {"knobs", k.knobs}, {"lacks", k.lacks}}.dump(2) + "\n");
    for (const xport::PasteText& t : xport::engineSnippets(e, k.knobs)) {
        writeTextAtomic(dir / t.file, t.text);
        std::fprintf(stderr, "wrote %s\n", (dir / t.file).string().c_str());
    }
}

int runExport(const ExportArgs& a) {
    const std::optional<xport::Engine> engine = xport::parseEngine(a.engine);
    if (!engine) {
        std::fprintf(stderr, "error: --to: unknown engine '%s'; expected one of: %s\n", a.engine.c_str(),
                     xport::engineList().c_str());
        return 2;
    }
    try {
        const Settings s = loadPreset(a.preset);
        const xport::EngineExport e = xport::exportSettings(s, *engine);
        const bool table = xport::hasKnobTable(*engine);
        if (!a.paste.empty() && !table) {
            std::fprintf(stderr, "error: --paste: %s has no knob table (engines with one: %s)\n", a.engine.c_str(),
                         xport::knobEngineList().c_str());
            return 2;
        }
        std::optional<xport::EngineKnobs> k;
        if (table) k = xport::knobsFor(*engine, s);
        std::string out;
        if (a.json) {
            nlohmann::ordered_json j = xport::toJson(e);
            if (k) j["knobs"] = k->knobs, j["lacks"] = k->lacks;
            out = j.dump(2) + "\n";
        } else {
            out = xport::toText(e) + (k ? knobsText(*engine, *k) : "");
        }
        if (k && !a.paste.empty()) writePaste(*engine, *k, a.paste);
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
    cmd->add_flag("--json", args->json,
                  "Print JSON: engine, title, exact, approximated, noEquivalent (and knobs, lacks for an engine with a knob table)");
    cmd->add_option("--paste", args->paste,
                    "Write ENGINE.json (the knob table's knobs and lacks) and the engine's paste-ready text into this folder "
                    "(engines with a knob table: " + xport::knobEngineList() + ")");
    cmd->callback([args, &exitCode] { exitCode = runExport(*args); });
}

}  // namespace st::app
