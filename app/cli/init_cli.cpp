// `shadowtune init SCENE.gltf|glb -o PRESET.json`: a preset for a scene of your own
// (app/scene_preset.h), validated and written atomically; needs no GL context.
#include "app/cli/commands.h"
#include "app/cli/preset_batch.h"
#include "app/scene_preset.h"

#include "renderer/settings/settings_json.h"

#include <glm/geometric.hpp>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

namespace st::app {
namespace fs = std::filesystem;

namespace {

struct InitArgs {
    fs::path scene, out;
    bool force = false;
};

int runInit(const InitArgs& a) {
    if (!isGltfPath(a.scene)) {
        std::fprintf(stderr, "error: %s: expected a .gltf or .glb file\n", a.scene.string().c_str());
        return 2;
    }
    const fs::path out = a.out.empty() ? fs::path(a.scene.stem().string() + ".json") : a.out;
    if (fs::exists(out) && !a.force) {
        std::fprintf(stderr, "error: %s exists; --force replaces it\n", out.string().c_str());
        return 2;
    }
    try {
        const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
        const Settings s = presetForScene(a.scene, dir);  // before the folder: a bad scene leaves nothing
        makeOutputDir(dir);
        savePresetAtomic(s, out);
        std::printf("wrote %s: %s, %d cascades to %.1f m, camera at %.1f m, %s\n", out.string().c_str(), s.scene.c_str(),
                    s.cascades.count, double(s.cascades.shadowDistance), double(glm::distance(s.camera.position, s.camera.target)),
                    s.ground ? "a ground added under it" : "its own floor takes the shadows");
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}

}  // namespace

void addInitCommand(CLI::App& cli, int& exitCode) {
    auto args = std::make_shared<InitArgs>();
    CLI::App* cmd = cli.add_subcommand("init", "Write a preset for a glTF scene of your own: framed camera, sun, ground if "
                                               "it has no floor, cascades spanning the scene");
    cmd->add_option("scene", args->scene, "The .gltf or .glb file")->required();
    cmd->add_option("-o,--out", args->out, "Preset to write (default: SCENE's name .json in the current folder)");
    cmd->add_flag("--force", args->force, "Replace an existing preset");
    cmd->callback([args, &exitCode] { exitCode = runInit(*args); });
}

}  // namespace st::app
