#pragma once
// Runs a sweep's points in one process, reusing the scene, the renderer, the BVH and the traced
// truth across points (metrics::MeasureSession), each point's result written to
// DIR/points/<id>.json as soon as it is measured (atomically), so a stopped run keeps its work and
// the next run resumes from it. Needs a current GL 4.5 context.
#include "metrics/cost_model.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace st::sweep {

struct Progress {
    std::size_t done = 0;      // of this run's points, including those found from a previous run
    std::size_t total = 0;
    std::size_t resumed = 0;   // found already measured
    double elapsedS = 0.0;     // this run
    double etaS = -1.0;        // -1 until a point has been measured
    std::string label;         // the point just finished
};

struct RunOptions {
    std::filesystem::path outDir;
    int shardIndex = 1;   // 1..shardCount
    int shardCount = 1;
    long stopAfter = -1;  // measure at most this many new points, then stop as an interrupt would
    std::function<bool()> stopRequested;  // checked between points (Ctrl-C)
    std::function<void(const Progress&)> progress;
    std::string machine;  // for the charts' subtitles
    ReportOptions report;
    int costFrames = 5;
    const metrics::CostProfile* costProfile = nullptr;  // models each point's cost (cost.modelMs)
};

struct RunOutcome {
    std::size_t measured = 0;
    std::size_t resumed = 0;
    std::size_t total = 0;  // this shard's points
    bool stopped = false;   // interrupted before the last point
    std::vector<std::string> front;
};

// Throws std::runtime_error for an output folder that holds another sweep's results.
RunOutcome runSweep(const SweepSpec& spec, const RunOptions& opt);

// Joins shard folders of one sweep into `outDir` and writes its report. Throws std::runtime_error
// naming the folder for one that is not a sweep folder or holds another sweep.
std::size_t mergeSweeps(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& outDir,
                        const ReportOptions& report);

// The point results found in `dir`, in the manifest's order.
std::vector<PointResult> readPoints(const std::filesystem::path& dir, const Manifest& m);

}  // namespace st::sweep
