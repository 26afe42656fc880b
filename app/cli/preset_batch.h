#pragma once
// What the headless commands (`render`, `measure`, ...) share: the output folder, the EGL
// context with its debug output, the check that a preset raised no serious GL message, and the
// loop over the presets given. A command supplies only its per-preset work.
#include <filesystem>
#include <functional>
#include <vector>

namespace st::app {

// Creates `dir` and its parents; throws std::runtime_error naming the folder and the reason.
void makeOutputDir(const std::filesystem::path& dir);

// Runs `one` on each preset; a preset whose `one` throws is reported and skipped, the rest still
// run.
// Returns the exit code: 1 if any preset failed, else 0.
int forEachPreset(const std::vector<std::filesystem::path>& presets,
                  const std::function<void(const std::filesystem::path&)>& one);

struct HeadlessRunOptions {
    std::vector<std::filesystem::path> presets;
    std::filesystem::path outDir;
    bool debugContext = false;  // KHR_debug context; a medium/high message fails the preset
};

// Writes one preset's outputs. It runs only after its GL work raised no serious debug message,
// so a preset that failed on the GPU leaves nothing behind.
using PresetWriter = std::function<void()>;
// One preset's GL work (throws to fail the preset); returns its writer (may be empty).
using PresetWork = std::function<PresetWriter(const std::filesystem::path& preset)>;
// Called once the context is current. The work it returns owns the command's GL state (scene
// caches, passes), which is released before the context is destroyed.
using PresetWorkFactory = std::function<PresetWork()>;

// Creates the output folder and a headless context, then runs the work on each preset through
// forEachPreset. Returns 2 if the folder, the context or the factory failed, else forEachPreset's
// exit code.
int runHeadless(const HeadlessRunOptions& opt, const PresetWorkFactory& start);

}  // namespace st::app
