#pragma once
// The Sweep panel's axis fields turned into a SweepRequest, or the reasons they cannot be: pure
// (no ImGui), so every message is tested. Values are checked with the preset reader's own rules
// (readFieldValue: kind, range, enum names), the same the sweep file reader applies later.
#include "renderer/settings/field_table.h"
#include "ui/compare_view.h"

#include <optional>
#include <string>
#include <vector>

namespace st::ui {

inline constexpr std::size_t kMaxEditorSweepPoints = 256;  // a sweep the editor waits for, not a batch job

struct AxisEdit {
    std::string field;        // a sweepable field path; empty: the axis is off
    bool range = false;       // values from `from` to `to` by `step`, else the `list`
    std::string list;         // "1, 2, 4" or "sphere, tight"
    double from = 0.0, to = 0.0, step = 0.0;
};

struct ParsedAxis {
    std::optional<SweepAxisRequest> axis;
    std::vector<std::string> errors;  // "axis 1 (cascades.count): ..." each
    std::size_t count = 0;            // values it gives
};

// `label` prefixes the messages ("axis 1").
ParsedAxis parseAxis(const AxisEdit& edit, const std::vector<std::string>& sweepable, const std::string& label);

// Both axes (an axis with no field is skipped; at least one is needed), their product bounded by
// kMaxEditorSweepPoints, and no field twice. Errors empty <=> request set.
struct ParsedSweep {
    std::optional<SweepRequest> request;
    std::vector<std::string> errors;
    std::size_t points = 0;
};
ParsedSweep parseSweep(const std::vector<AxisEdit>& axes, const std::vector<std::string>& sweepable, int width,
                       int height);

}  // namespace st::ui
