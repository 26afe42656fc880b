#pragma once
// Per-preset golden tolerances (tests/render/golden_tolerances.json): a preset may carry its own
// image tolerance, and must say why. Presets without an entry take the default.
#include "tests/support/image_compare.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace st::test {

struct GoldenTolerance {
    Tolerance tolerance;
    std::string reason;       // why this tolerance: the default's, or the override's own
    bool overridden = false;  // the preset has an entry of its own
    std::string describe() const;  // "5/255 per channel, 0.1 % of pixels (default: ...)"
};

// The table's tolerance for `preset` (a preset file's stem). The table is
//   {"default": T, "presets": {"<stem>": T, ...}},  T = {"maxChannelDiff": int,
//   "maxFailingFraction": number, "reason": "why"}.
// Throws std::runtime_error for a malformed table: unknown keys, values out of range
// (0..255, 0..1) or an empty reason.
GoldenTolerance toleranceFor(const nlohmann::json& table, std::string_view preset);

nlohmann::json readToleranceTable(const std::filesystem::path& file);  // throws std::runtime_error

}  // namespace st::test
