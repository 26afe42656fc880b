#pragma once
// The editor's panel layout (column widths, hidden panels) in <config dir>/layout.json: the
// editor's own file, kept across runs, never part of a preset.
#include "ui/item_rects.h"
#include "ui/layout.h"

#include <imgui.h>

#include <filesystem>

namespace st::app {

// Defaults for a missing or unreadable file, and for each missing or mistyped member: a broken
// layout file is no reason not to open the editor.
ui::LayoutPrefs loadLayoutPrefs(const std::filesystem::path& file);
// Atomic; a failure is reported on stderr and otherwise ignored (it runs at exit).
void saveLayoutPrefs(const std::filesystem::path& file, const ui::LayoutPrefs& prefs);

// --layout-report: {"display": [w, h], "scene": [x, y, w, h], "windows": {"Settings": [x, y, w, h],
// ...}, "items": {...}}, ImGui's display pixels from the top left, as the last frame placed them.
void writeLayoutReport(const std::filesystem::path& file, const ui::ItemRects& rects, ImVec2 display,
                       ImVec2 scenePos, ImVec2 sceneSize);

}  // namespace st::app
