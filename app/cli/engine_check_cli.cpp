// `shadowtune engine-check`: options and their validation (app/cli/engine_check_command.h).
#include "app/cli/commands.h"
#include "app/cli/engine_check_command.h"
#include "app/cli/size_option.h"

#include <cstdio>
#include <memory>
#include <string>

namespace st::app {
namespace {

struct EngineCheckArgs {
    EngineCheckOptions opt;
    std::string engine, size;
};

int runArgs(EngineCheckArgs& a) {
    const auto engine = xport::parseKnobEngine(a.engine);
    if (!engine || !xport::runsHere(*engine)) {
        std::fprintf(stderr, "error: --engine: '%s' is not one of %s%s\n", a.engine.c_str(), xport::loopEngineList().c_str(),
                     engine ? " (the engines that run here; its model is a reading of its source, docs/engines.md)" : "");
        return 2;
    }
    a.opt.engine = *engine;
    if (!a.size.empty()) {
        const auto size = parseSize(a.size);
        if (!size) {
            std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", a.size.c_str());
            return 2;
        }
        a.opt.width = size->first;
        a.opt.height = size->second;
    }
    if (a.opt.defaults && !a.opt.knobsFile.empty()) {
        std::fprintf(stderr, "error: --defaults and --knobs exclude each other\n");
        return 2;
    }
    return runEngineCheck(a.opt);
}

}  // namespace

void addEngineCheckCommand(CLI::App& cli, int& exitCode) {
    auto args = std::make_shared<EngineCheckArgs>();
    CLI::App* cmd = cli.add_subcommand(
        "engine-check", "Render a preset's view in the real engine (three.js, Babylon.js) and in shadowtune's model of it; "
                        "score both against the ray-cast truth and report their pixel agreement");
    cmd->add_option("preset", args->opt.preset, "Preset JSON file: its scene, camera, sun and size")->required();
    cmd->add_option("--engine", args->engine, "Engine: " + xport::loopEngineList())->required();
    cmd->add_option("--out", args->opt.outDir, "Output folder")->capture_default_str();
    cmd->add_option("--size", args->size, "Output size WxH (default: the preset's)");
    cmd->add_flag("--defaults", args->opt.defaults, "Use the engine's default shadow settings, not the preset's");
    cmd->add_option("--knobs", args->opt.knobsFile, "JSON file of the engine's own knobs (its names and units)");
    cmd->add_option("--engines-dir", args->opt.enginesDir, "The engines/ folder with run.mjs (default: the source tree's)");
    cmd->add_option("--model-set", args->opt.modelSets,
                    "PATH=JSON: change one field of shadowtune's model (e.g. cascades.casterFaces=\"both\"), to see how far "
                    "the agreement falls when the model is wrong");
    cmd->add_option("--subpixel-bits", args->opt.subpixelBits,
                    "Sub-pixel bits of the engine's rasterizer, for the model to snap vertices alike (0: this GPU's own)")
        ->capture_default_str()
        ->check(CLI::Range(0, 8));
    cmd->add_flag("--debug-context,!--no-debug-context", args->opt.debugContext, "KHR_debug context");
    cmd->callback([args, &exitCode] { exitCode = runArgs(*args); });
}

}  // namespace st::app
