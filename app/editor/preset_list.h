#pragma once
// The presets the editor offers: the preset folder and its sub-folders (scenes/, scenarios/,
// engines/, ...), without sweeps/, whose files are sweep definitions, not presets.
#include <filesystem>
#include <vector>

namespace st::app {

// Every *.json under `dir`, sub-folders included except those named "sweeps"; the files of `dir`
// itself first, then each sub-folder's, each group sorted by path. A missing folder gives none.
std::vector<std::filesystem::path> listPresetFiles(const std::filesystem::path& dir);

}  // namespace st::app
