#pragma once
// Widgets for the few fields whose presentation needs more than their own table row: the scene
// (built-in names from renderer/scene plus a glTF path), the map size (memory it costs, which
// depends on the cascade count) and the manual splits (shown for the manual scheme only, always
// cascades.count - 1 long) and the per-cascade bias factors (empty, or one per cascade). Everything else uses the generic widget of its kind.
#include "ui/ui_state.h"

#include <string_view>

namespace st::ui {

// Draws the field and returns whether it changed `f.s`.
using FieldOverride = bool (*)(const FieldInfo& field, UiFrame& f);

FieldOverride overrideFor(std::string_view path);  // nullptr: use drawFieldWidget

}  // namespace st::ui
