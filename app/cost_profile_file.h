#pragma once
// Which cost profile a command models cost with: --profile FILE, else the shipped default for
// Mesa llvmpipe beside the presets the binary uses (presets/cost-profiles/llvmpipe.json in a
// source checkout, <prefix>/share/shadowtune/presets/cost-profiles/llvmpipe.json installed).
#include "metrics/cost_model.h"

#include <filesystem>

namespace st::app {

// <presetDir>/cost-profiles/llvmpipe.json.
std::filesystem::path defaultCostProfileFor(const std::filesystem::path& presetDir);
std::filesystem::path defaultCostProfile();  // of defaultPresetDir()

// `option` when given, else defaultCostProfile(). Throws metrics::CostProfileError naming the
// file, the JSON path and the reason.
metrics::CostProfile loadCostProfileOption(const std::filesystem::path& option);

}  // namespace st::app
