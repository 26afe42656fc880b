#pragma once
// Colours the panels share, so a message means the same colour everywhere.
#include <imgui.h>

namespace st::ui {

inline const ImVec4 kErrorColour{1.0f, 0.35f, 0.3f, 1.0f};  // refused values, failures, stale figures

}  // namespace st::ui
