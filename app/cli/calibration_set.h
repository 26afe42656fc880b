#pragma once
// The fixed set of frames `shadowtune calibrate` times: the shipped presets, scenarios, engine and
// scene presets, plus variants of map size, cascade count, filter and depth bounds, so the fit sees
// the whole range of work the sweeps ask for (docs/cost-model.md).
#include "renderer/settings/settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::app {

struct CalibrationPoint {
    std::string name;                 // "default@320x180", "truck-town count=1 mapSize=512"
    Settings settings;
    std::filesystem::path presetDir;  // relative scene paths resolve against it
};

// Which points of a sweep join the calibration set: every kSweepEvery-th from the kSweepFirst-th
// (0-based). scripts/bench_cost_model.sh checks points 0, 7, 14, ... (`--check --every 7`), so
// the shipped sweeps' points it judges the model on are never the ones it was fitted on.
inline constexpr std::size_t kSweepFirst = 3, kSweepEvery = 7;

// The set, read from `presetDir` (the shipped presets folder), then the chosen points of `sweeps`
// (empty: presetDir/sweeps/*.json): scenes the way they are tuned, with their own triangle sizes.
// `size` overrides every point's output size. Throws SettingsError naming the preset or sweep and
// the problem when one is missing or invalid.
std::vector<CalibrationPoint> calibrationSet(const std::filesystem::path& presetDir,
                                             std::optional<std::pair<int, int>> size = std::nullopt,
                                             std::vector<std::filesystem::path> sweeps = {});

}  // namespace st::app
