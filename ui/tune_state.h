#pragma once
// What the Tune panel remembers between frames (part of UiState). Internal to ui/.
#include "renderer/settings/settings.h"
#include "ui/tune_view.h"

#include <optional>
#include <string>

namespace st::ui {

struct TuneUiState {
    bool show = false;
    TuneRequest edit;                   // the panel's fields
    std::string applied;                // "applied the tuned settings", while the settings are still
    std::optional<Settings> appliedAs;  // what the apply made them
};

// Opens the Tune panel with the objective a piece of advice asks for.
void openTuneFor(TuneUiState& t, const std::string& adviceRule);

}  // namespace st::ui
