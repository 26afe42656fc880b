#pragma once
// `shadowtune sweep`: runs a sweep file (or merges shard folders) with progress on the terminal.
#include <filesystem>
#include <string>
#include <vector>

namespace st::app {

struct SweepCommandOptions {
    std::filesystem::path sweepFile;
    std::filesystem::path outDir;
    std::string shard;                          // "k/n", empty for the whole sweep
    std::vector<std::filesystem::path> merge;   // shard folders to join instead of running
    std::string error = "misclassified";
    std::string cost = "model";  // the x axis of pareto.png and the front (figure table CostChoice rows)
    long stopAfter = -1;
    int costFrames = 5;
    std::filesystem::path costProfile;  // --profile; empty: the shipped llvmpipe profile
    bool debugGl = false;
};

// The process exit code: 0 done (or stopped by --stop-after), 1 bad input, 2 GL or output
// trouble, 130 interrupted by Ctrl-C (results kept; run again to resume).
int runSweepCommand(const SweepCommandOptions& opt);

}  // namespace st::app
