#pragma once
// metrics.json: every figure of a PresetMeasurement, machine-readable. Shares are fractions of
// the receivers (pixels facing the sun), as docs/architecture.md defines them; counts are pixels.
// The detail (per cascade, pixel counts, settings echoes) is written here; every row of `table`
// shown in metrics.json is then set at its key's path, so a figure added to the table appears
// with no other edit (docs/metrics.md lists them).
#include "metrics/figure_table.h"
#include "metrics/measure_session.h"

#include <nlohmann/json.hpp>

#include <string>

namespace st::metrics {

nlohmann::ordered_json toJson(const PresetMeasurement& m, const std::string& presetName,
                              const FigureTable& table = figureTable());

}  // namespace st::metrics
