#pragma once
// The editor's Engine choice (issue "Tune for your engine", item 5): with an engine chosen, the
// Settings panel shows that engine's knobs in its own names (renderer/export/engine_knobs.h),
// greys the settings the engine has no knob for, shows the paste-ready text, and the Tune panel
// tunes in the engine's knobs only. Internal to ui/.
#include "renderer/export/engine_export.h"

#include <optional>
#include <string>

namespace st::ui {

struct EngineUiState {
    std::optional<xport::Engine> engine;  // none: shadowtune's every method
    std::string error;                    // the last knob edit the engine's model refused
    std::string saved;                    // "saved threejs.js to ..." after Save
};

}  // namespace st::ui
