#pragma once
// `shadowtune calibrate`: fits the cost model (metrics/cost_model.h) on this machine and writes
// the profile; with --check, times sweep points instead and prints how well a profile's modelled
// cost follows the measured times.
#include <filesystem>
#include <string>
#include <optional>
#include <utility>
#include <vector>

namespace st::app {

struct CalibrateOptions {
    std::filesystem::path out = "cost-profile.json";
    int frames = 5;                              // timed frames per preset, after one untimed
    std::optional<std::pair<int, int>> size;     // override every point's output size
    std::filesystem::path presetDir;             // empty: defaultPresetDir()
    // Sweeps whose points join the calibration set (calibration_set.h); empty: the shipped ones.
    std::vector<std::filesystem::path> sweeps;
    // --check: the sweeps whose points are timed against `profile` (empty: the shipped default).
    std::vector<std::filesystem::path> check;
    int every = 1;                               // every k-th point of each sweep
    // Passes over all the points, each point's frames joined over them: the machine's speed
    // drifts over minutes, and the minimum over passes spread in time drifts less.
    int passes = 1;
    std::filesystem::path profile;
    // --refit: the pass kind ("depthBounds") refitted alone on its own timers, the other kinds
    // kept from `profile`; only the calibration points that run it are timed.
    std::string refit;
    // --samples: every timed point's counted work and frame times, one JSON object per line, so a
    // profile can be refitted (or features tried) without timing again.
    std::filesystem::path samples;
    bool debugContext = false;
};

// Progress on stderr, one line per preset (or point); the result on stdout. Returns the exit code.
int runCalibrate(const CalibrateOptions& opt);

}  // namespace st::app
