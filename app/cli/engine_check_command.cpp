#include "app/cli/engine_check_command.h"

#include "app/cli/engine_check_outputs.h"
#include "app/cli/preset_batch.h"
#include "app/editor/child_run.h"
#include "metrics/measure_session.h"
#include "renderer/csm/light_fit.h"
#include "renderer/image/image_io.h"
#include "renderer/scene/glb_write.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::app {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

fs::path enginesDirOf(const EngineCheckOptions& opt) {
    if (!opt.enginesDir.empty()) return opt.enginesDir;
    if (const char* env = std::getenv("ST_ENGINES_DIR"); env && *env) return env;
    return fs::path(ST_SOURCE_DIR) / "engines";
}

json vec3Json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// The scene as the engine loads it: the preset's glTF with the engine's own loader, plus what
// exists only inside shadowtune (a built-in scene, the ground quad) as a .glb of its draws.
json sceneJob(const Settings& s, const fs::path& presetDir, const fs::path& out) {
    json scene = {{"gltf", nullptr}, {"extra", nullptr}};
    const bool builtin = s.scene.rfind("builtin:", 0) == 0;
    if (!builtin) scene["gltf"] = fs::absolute(presetDir / s.scene).lexically_normal().string();
    if (!builtin && !s.ground) return scene;
    Scene loaded = loadScene(s.scene, presetDir);
    const std::size_t first = builtin ? 0 : loaded.draws.size();
    if (s.ground) addGroundUnder(loaded);
    const fs::path glb = fs::absolute(out / "scene-extra.glb");
    writeTextAtomic(glb, glbOfDraws(loaded, first));
    scene["extra"] = glb.string();
    return scene;
}

json jobOf(xport::Engine e, const Settings& s, const json& knobs, const json& scene, const fs::path& out) {
    const CameraSettings& c = s.camera;
    return {{"engine", xport::engineName(e)},
            {"width", s.output.width},
            {"height", s.output.height},
            {"scene", scene},
            {"camera", {{"position", vec3Json(c.position)}, {"target", vec3Json(c.target)}, {"fovY", c.fovY},
                        {"near", c.nearPlane}, {"far", c.farPlane}}},
            {"sun", {{"direction", vec3Json(csm::lightDirection(s.light.azimuth, s.light.elevation))}}},
            {"settings", knobs},
            {"out", fs::absolute(out / "engine").string()}};
}

// The knobs this check gives the engine, and what of the preset the engine lacks.
xport::EngineKnobs knobsOf(const EngineCheckOptions& opt, const Settings& preset) {
    if (opt.defaults) return {xport::defaultKnobs(opt.engine), {}};
    if (!opt.knobsFile.empty()) return {loadJsonFile(opt.knobsFile, "engine knobs"), {}};
    return xport::knobsFor(opt.engine, preset);
}

std::vector<glm::vec4> readSamples(const fs::path& file, int width, int height) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": the engine wrote no samples");
    std::vector<glm::vec4> v(std::size_t(width) * std::size_t(height));
    in.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * sizeof(glm::vec4)));
    if (in.gcount() != std::streamsize(v.size() * sizeof(glm::vec4)) || in.peek() != EOF)
        throw std::runtime_error(file.string() + ": expected " + std::to_string(width) + "x" + std::to_string(height) +
                                 " pixels of 4 floats");
    return v;
}

// The engine's child: 0 once it has written its samples; else the reason, and 2 for an engine
// that could not start (the driver's own exit code 2, or env's 127 for a missing node).
int waitForEngine(pid_t child, const fs::path& log) {
    int status = 0;
    ::waitpid(child, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
    std::fprintf(stderr, "error: the engine failed (%s); %s:\n", exitText(status).c_str(), log.string().c_str());
    if (code == 127) std::fprintf(stderr, "  node is not installed: run scripts/setup.sh\n");
    for (const std::string& line : lastLines(log, 8)) std::fprintf(stderr, "  %s\n", line.c_str());
    return code == 2 || code == 127 ? 2 : 1;
}

// --model-set PATH=JSON: read exactly as a preset's field would be.
void applyModelSets(const std::vector<std::string>& sets, Settings& model) {
    for (const std::string& set : sets) {
        const auto eq = set.find('=');
        const FieldInfo* field = eq == std::string::npos ? nullptr : findField(set.substr(0, eq));
        if (!field) throw std::invalid_argument("--model-set: expected FIELD=JSON with a field of the preset, got '" + set + "'");
        const json value = json::parse(set.substr(eq + 1), nullptr, false);
        if (value.is_discarded()) throw std::invalid_argument("--model-set " + set + ": the value is not JSON (quote strings)");
        field->set(model, readFieldValue(*field, value, std::string(field->path)));
    }
}

}  // namespace

int runEngineCheck(const EngineCheckOptions& opt) {
    const auto started = Clock::now();
    Settings preset, model;
    xport::EngineKnobs knobs;
    json job;
    const fs::path enginesDir = enginesDirOf(opt);
    try {
        preset = loadPreset(opt.preset);
        if (opt.width) preset.output.width = *opt.width;
        if (opt.height) preset.output.height = *opt.height;
        knobs = knobsOf(opt, preset);
        model = xport::engineModel(opt.engine, knobs.knobs, preset);
        applyModelSets(opt.modelSets, model);
        if (!fs::exists(enginesDir / "run.mjs"))
            throw std::runtime_error(enginesDir.string() + "/run.mjs is missing: pass --engines-dir");
        makeOutputDir(opt.outDir);
        job = jobOf(opt.engine, model, knobs.knobs, sceneJob(preset, folderOf(opt.preset), opt.outDir), opt.outDir);
        writeTextAtomic(opt.outDir / "job.json", job.dump(2) + "\n");
        Settings saved = model;  // loadable from the output folder
        saved.scene = absoluteScene(model.scene, folderOf(opt.preset));
        savePresetAtomic(saved, opt.outDir / "model.json");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
    for (const std::string& l : knobs.lacks)
        if (!opt.quiet) std::printf("%s lacks: %s\n", xport::engineName(opt.engine).c_str(), l.c_str());
    std::string error;
    const fs::path log = opt.outDir / "engine.log";
    const pid_t child = spawnLogged({"/usr/bin/env", "node", (enginesDir / "run.mjs").string(),
                                     fs::absolute(opt.outDir / "job.json").string()},
                                    log, error);
    if (child < 0) {
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return 2;
    }
    // shadowtune's half runs while the engine starts: the same view, the model's settings.
    auto result = std::make_shared<int>(0);
    const fs::path modelPreset = opt.outDir / "model.json";
    const int gl = runHeadless({{modelPreset}, opt.outDir, opt.debugContext}, [&]() -> PresetWork {
        return [&](const fs::path&) -> PresetWriter {
            metrics::MeasureSession session;
            metrics::MeasureOptions mo;
            mo.cost = false;
            mo.flicker = false;
            mo.subpixelSteps = opt.subpixelBits > 0 ? 1 << opt.subpixelBits : 0;
            auto m = std::make_shared<metrics::PresetMeasurement>(session.measure(model, folderOf(opt.preset), mo));
            return [&, m] {
                if ((*result = waitForEngine(child, log)) != 0) return;
                const auto engine = readSamples(opt.outDir / "engine" / "samples.f32", model.output.width, model.output.height);
                const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
                *result = writeEngineCheck(opt, knobs, *m, engine, seconds);
            };
        };
    });
    if (gl != 0) {
        stopChild(child);
        return gl;
    }
    return *result;
}

}  // namespace st::app
