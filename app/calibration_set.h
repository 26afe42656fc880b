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

// The set, read from `presetDir` (the shipped presets folder). `size` overrides every point's
// output size. Throws SettingsError naming the preset and the problem when a shipped preset is
// missing or invalid.
std::vector<CalibrationPoint> calibrationSet(const std::filesystem::path& presetDir,
                                             std::optional<std::pair<int, int>> size = std::nullopt);

}  // namespace st::app
