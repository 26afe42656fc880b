#pragma once
// metrics.json: every figure of a PresetMeasurement, machine-readable. Shares are fractions of
// the receivers (pixels facing the sun), as docs/architecture.md defines them; counts are pixels.
#include "metrics/measure_session.h"

#include <nlohmann/json.hpp>

#include <string>

namespace st::metrics {

nlohmann::ordered_json toJson(const PresetMeasurement& m, const std::string& presetName);

}  // namespace st::metrics
