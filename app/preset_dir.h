#pragma once
// Where the editor looks for presets: ./presets in a source checkout, else the installed copy.
#include <filesystem>

namespace st::app {

// "presets" (relative, as the editor shows it) when `cwd`/presets is a folder; else
// <exe dir>/../share/shadowtune/presets when that is one (an installed shadowtune run from any
// folder); else "presets", which the editor treats as an empty list.
std::filesystem::path presetDirFor(const std::filesystem::path& cwd, const std::filesystem::path& exe);

// presetDirFor(the current folder, /proc/self/exe).
std::filesystem::path defaultPresetDir();

}  // namespace st::app
