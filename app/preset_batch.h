#pragma once
// What `render` and `measure` share: the output folder and the loop over the presets given.
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

}  // namespace st::app
