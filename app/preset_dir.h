#pragma once
// Where the editor looks for presets: ./presets in a source checkout, else the installed copy.
#include <filesystem>

namespace st::app {

// "presets" (relative, as the editor shows it) when `cwd`/presets is a folder; else the nearest
// folder named "presets" that holds `opened` (a preset opened by its path from elsewhere:
// .../presets/scenarios/x.json lists .../presets); else <exe dir>/../share/shadowtune/presets
// when that is one (an installed shadowtune run from any folder); else "presets", which the
// editor treats as an empty list.
std::filesystem::path presetDirFor(const std::filesystem::path& cwd, const std::filesystem::path& exe,
                                   const std::filesystem::path& opened = {});

// presetDirFor(the current folder, /proc/self/exe, opened).
std::filesystem::path defaultPresetDir(const std::filesystem::path& opened = {});

}  // namespace st::app
