#pragma once
// What the A/B split and the Sweep panel remember between frames (part of UiState). Internal to ui/.
#include "renderer/settings/settings.h"
#include "ui/sweep_axes.h"

#include <optional>
#include <string>
#include <vector>

namespace st::ui {

struct CompareUiState {
    std::optional<Settings> a;  // "Set as A": a snapshot of the settings
    bool split = false;         // the split view is on (needs A)
    float divider = 0.5f;       // fraction of the window's width

    bool showSweep = false;
    std::vector<AxisEdit> axes{AxisEdit{"cascades.count", false, "1, 2, 3, 4", 0.0, 0.0, 0.0},
                               AxisEdit{"cascades.mapSize", false, "512, 1024, 2048", 0.0, 0.0, 0.0}};
    int width = 320, height = 180;
    bool byMemory = false;      // the chart's x axis: memory instead of GPU time
    std::string applied;        // the last point a click applied ("applied count=2 ..."), while
    std::optional<Settings> appliedAs;  // the settings are still what it made them
};

}  // namespace st::ui
