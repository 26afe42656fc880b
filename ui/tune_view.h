#pragma once
// What the Tune panel shows and asks for, as plain values (ui/ includes neither the tuner nor GL):
// the app runs `shadowtune tune` in the background (app/editor/editor_tune.h) and fills a TuneView from
// its progress.json and, at the end, its explanation.
#include "renderer/settings/settings.h"
#include "ui/compare_view.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::ui {

struct TuneRequest {
    enum class Budget { AsNow, Ms, MiB };
    Budget budget = Budget::AsNow;  // AsNow: the live settings' own modelled cost and memory
    double ms = 0.0;                // Budget::Ms: modelled frame cost at most this
    double mib = 0.0;               // Budget::MiB: map memory at most this
    std::string objective = "soft-filtered";  // a `tune --objective` choice
    int evaluations = 24;
    int views = 3;                  // the camera and viewpoints around it; the last one is held out
    int width = 320, height = 180;  // measured at this size
    bool front = false;             // `tune --front`: a quarter of the evaluations descend to cheaper settings
    std::string engine;             // `tune --engine`: the Engine section's choice; empty: every method
    bool operator==(const TuneRequest&) const = default;
};

// One line of the explanation, with what applying it alone sets.
struct TuneChange {
    std::string line;       // "Shadow distance (m) 0 -> 250: alone -0.33 pp ..., in the tuned preset ..."
    std::string path;       // the field
    std::string valueJson;  // its tuned value, as JSON text
    // Fields set first with it, as JSON text (manual splits come with the manual scheme).
    std::vector<std::pair<std::string, std::string>> with;
};

struct TuneView {
    enum class State { Idle, Running, Cancelling, Done, Cancelled, Failed };
    State state = State::Idle;
    std::string stage;       // progress.json's: searching, explaining, done, stopped, infeasible
    int done = 0, total = 0; // evaluations made of the limit
    double elapsedS = 0.0;
    std::string best;        // "best 0.518 % at 74.1 ms", or "nothing within the budget yet"
    std::string budget;      // "budget 75.2 ms and 12.0 MiB"
    std::vector<std::string> errors;  // Failed: why (the child's last lines)
    std::string folder;      // the tune's output folder (tuned.json, front/, explain.md)
    SweepView chart;         // the evaluations, "current" and "A", for drawParetoPlot
    std::vector<TuneChange> changes;  // Done: the explanation, one line per changed field
    std::string result;      // Done: "tuned 0.52 % misclassified at 74.1 ms (current 0.84 % at 75.3 ms)"
    std::string heldOut;     // Done: how it does on the held-out view
    std::vector<std::string> worse;  // Done: artifact figures the tuned settings have more of, as sentences
    std::optional<Settings> measuredFrom;  // the live settings the run started from
};

// The objective a piece of advice asks for ("Tune for this"): its rule's own artifact class, or
// misclassified pixels for a resolution problem.
std::string tuneObjectiveFor(const std::string& adviceRule);

}  // namespace st::ui
