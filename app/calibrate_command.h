#pragma once
// `shadowtune calibrate`: fits the cost model (metrics/cost_model.h) on this machine and writes
// the profile; with --check, times sweep points instead and prints how well a profile's modelled
// cost follows the measured times.
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

namespace st::app {

struct CalibrateOptions {
    std::filesystem::path out = "cost-profile.json";
    int frames = 5;                              // timed frames per preset, after one untimed
    std::optional<std::pair<int, int>> size;     // override every point's output size
    std::filesystem::path presetDir;             // empty: defaultPresetDir()
    // --check: the sweeps whose points are timed against `profile` (empty: the shipped default).
    std::vector<std::filesystem::path> check;
    int every = 1;                               // every k-th point of each sweep
    std::filesystem::path profile;
    bool debugContext = false;
};

// Progress on stderr, one line per preset (or point); the result on stdout. Returns the exit code.
int runCalibrate(const CalibrateOptions& opt);

}  // namespace st::app
