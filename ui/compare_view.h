#pragma once
// What the A/B split and the Sweep panel show, as plain values the app fills in (ui/ includes
// neither the sweep library nor GL), and what the Sweep panel asks the app to run.
#include "renderer/render/frame_stats.h"
#include "renderer/settings/settings.h"
#include "ui/accuracy_view.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::ui {

// The A half of the split: its frame's figures and its own ground-truth job.
struct AbView {
    const FrameStats* stats = nullptr;  // nullptr: not rendered (yet)
    AccuracyView accuracy;
};

// One measured point of the sweep, in the units the chart shows (the app picks the figures from
// the figure table: its cost, memory and error choices, and scales them for display).
struct SweepPoint {
    std::string label;          // "count=2 mapSize=1024", or a reference's name ("current", "A")
    bool reference = false;
    double cost = 0.0;          // the cost choice, e.g. GPU ms
    double memory = 0.0;        // map memory, MiB
    double error = 0.0;         // the error choice, e.g. misclassified %
    bool frontByTime = false;   // on the Pareto front of (cost, error)
    bool frontByMemory = false; // ... of (memory, error)
    std::string figures;        // the tooltip's lines of figures
    // What a click applies to the document: field path -> value as JSON text.
    std::vector<std::pair<std::string, std::string>> assignments;
};

struct SweepView {
    enum class State { Idle, Running, Cancelling, Done, Cancelled, Failed };
    State state = State::Idle;
    std::size_t done = 0, total = 0;  // points measured of the sweep's points
    double elapsedS = 0.0;
    double etaS = -1.0;               // -1 until a point is in
    std::vector<std::string> errors;  // Failed: why (refused sweep, the child's last lines)
    std::string folder;               // where results.csv, pareto.png, ... are written
    std::string scene;                // what the sweep measured, for the chart's title
    int width = 0, height = 0;
    std::vector<SweepPoint> points;   // those measured so far
    std::optional<Settings> measuredFrom;  // the live settings the run started from (its camera, sun, scene)
    // The chart's axis titles and the cost's short name (the figure table's rows).
    std::string costTitle = "cost", memoryTitle = "memory", errorTitle = "error", costName = "cost";
};

// One axis the panel asks for: a sweepable field and its values as the sweep file spells them.
struct SweepAxisRequest {
    std::string field;
    nlohmann::json values;  // a list of values, or {"from", "to", "step"} (key "range")
    bool range = false;
};

struct SweepRequest {
    std::vector<SweepAxisRequest> axes;  // one or two
    int width = 320, height = 180;       // measured at this size (the ground truth is per pixel)
};

}  // namespace st::ui
