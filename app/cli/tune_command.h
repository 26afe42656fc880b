#pragma once
// `shadowtune tune`: the best settings for a preset's scene within a cost budget, found by search
// and explained (tune/tune_run.h).
#include "renderer/export/engine_knobs.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::app {

struct TuneCommandOptions {
    std::filesystem::path preset;
    std::filesystem::path outDir;
    std::optional<double> budgetMs, budgetMiB;
    std::vector<std::filesystem::path> budgetFrom;
    std::vector<std::filesystem::path> compareWith;
    bool sharedRenderer = false;
    std::string objective = "soft-filtered";
    int views = 4;
    int holdOutEvery = 4;
    std::uint64_t seed = 1;
    int evaluations = 80;
    bool noConstraints = false;  // --constraints none
    bool front = false;
    std::optional<xport::Engine> engine;  // --engine: that engine's knobs only
    bool noEngineCheck = false;            // --no-engine-check: skip the proof in the engine (tune_engine_proof.h)
    long stopAfter = -1;
    std::optional<std::pair<int, int>> size;  // override the preset's output size
    std::filesystem::path costProfile;  // empty: the shipped llvmpipe profile
    bool debugGl = false;
    int shardIndex = 1, shardCount = 1;  // --shard k/n
    double shardWaitSeconds = 600.0;
};

// Exit codes: 0 tuned; 1 bad input, or no settings within the budget (the message names the
// cheapest cost); 2 cannot run (no GL context, GL errors); 130 interrupted (the journal keeps the
// evaluations made: the same command resumes).
int runTuneCommand(const TuneCommandOptions& opt);

}  // namespace st::app
