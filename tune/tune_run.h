#pragma once
// One tune, end to end (docs/tuning.md): reads the preset and the budget, checks the budget can be
// met at all, searches (tune_search.h) with every evaluation journaled so Ctrl-C keeps it and the
// same command resumes, scores the result on held-out views, explains each change by ablation,
// and writes tuned.json, front/, explain.json/.md and summary.json. While it runs, progress.json
// (rewritten atomically before each evaluation) says how far it is, for a UI to draw (the editor's
// Tune panel). Needs a current GL context.
#include "metrics/cost_model.h"
#include "renderer/export/engine_knobs.h"
#include "tune/tune_journal.h"
#include "tune/tune_search.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::tune {

struct TuneOptions {
    std::filesystem::path preset;
    std::filesystem::path outDir;
    std::optional<double> budgetMs;                  // modelled frame cost
    std::optional<double> budgetMiB;                 // map memory
    std::vector<std::filesystem::path> budgetFrom;   // references: the cheapest one's cost and memory
    // Presets measured on the same views and drawn on the front (the editor's A), but neither a
    // budget nor a baseline nor a constraint.
    std::vector<std::filesystem::path> compareWith;
    std::optional<std::pair<int, int>> size;         // override the preset's output size
    std::string objective = "soft-filtered";         // a figure table --error choice
    int views = 4;                                   // the preset's camera and views around it
    int holdOutEvery = 4;                            // every k-th view after the first is held out
    std::uint64_t seed = 1;
    // The last quarter polish the best point's depths and bias (kPolishShare, SearchOptions::polish).
    int evaluations = 80;
    // The soft truth's artifact classes (and a path's flicker) may not get worse than the input's
    // and the references' (false: the objective alone, as a sweep's front ranks points).
    bool constraints = true;
    // Keep a quarter of the evaluations for a descent to cheaper settings from the tuned point
    // (SearchOptions::front): front/ and summary.json's "front" then hold the cost-error front
    // of every point within the budget, judged on the objective alone (docs/tuning.md#front).
    bool front = false;
    const metrics::CostProfile* profile = nullptr;
    std::function<bool()> stopRequested;
    long stopAfter = -1;  // make at most this many new evaluations, then stop as Ctrl-C would
    std::function<void(const std::string&)> progress;  // one line per evaluation and stage
    std::string machine;
    // One of n processes on one shared folder (docs/tuning.md#shards): each measures its share of
    // every round and waits for the others'. The first shard writes the outputs.
    Shard shard;
    double shardWaitSeconds = 600.0;  // then a silent shard's share is measured here
    // Each view keeps its own renderer and maps (ViewEvaluator::setRendererPerView); false: the
    // baseline that redraws every map at every change of view (scripts/bench_tune.sh's ratio).
    bool rendererPerView = true;
    // Tune for this engine (tune_engine.h): its knobs only; tuned.json is what it renders, and
    // <engine>.json / <engine>.js its knobs and paste-ready text.
    std::optional<xport::Engine> engine;
};

struct TuneOutcome {
    bool stopped = false;      // Ctrl-C: what was measured is kept; the same command resumes
    bool infeasible = false;   // no settings within the budget (message names the cheapest cost)
    std::string message;       // the summary line
    int evaluations = 0;       // made by this run (a resumed run's journal ones are free)
    int resumed = 0;           // read back from the journal
    int fromShards = 0;        // measured by other shards and read from their journals
};

// Throws SettingsError for a bad preset or reference, std::runtime_error for a folder holding
// another tune.
TuneOutcome runTune(const TuneOptions& opt);

}  // namespace st::tune
