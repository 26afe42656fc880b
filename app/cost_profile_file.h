#pragma once
// Which cost profile a command models cost with: --profile FILE, else the shipped default for
// Mesa llvmpipe (presets/cost-profiles/llvmpipe.json), compiled into the binary so a command
// models the same cost from any folder; the installed copy under
// <prefix>/share/shadowtune/presets/cost-profiles/ is there to read and to pass as --profile.
#include "metrics/cost_model.h"

#include <filesystem>
#include <memory>
#include <string_view>

namespace st::app {

// <presetDir>/cost-profiles/llvmpipe.json: where the shipped profile's file lives.
std::filesystem::path defaultCostProfileFor(const std::filesystem::path& presetDir);

// The shipped profile's JSON text, as compiled in (generated from the file at build time).
std::string_view defaultCostProfileText();

// `option` when given, else the compiled-in default. Throws metrics::CostProfileError naming the
// file, the JSON path and the reason.
metrics::CostProfile loadCostProfileOption(const std::filesystem::path& option);
// The same for a command's start: null after printing "error: ..." on stderr (exit 1: bad input).
std::shared_ptr<const metrics::CostProfile> loadCostProfileOrReport(const std::filesystem::path& option);

}  // namespace st::app
