#pragma once
// What `engine-check` writes once both renders are in: the images with legends, figures.json and
// the printed table (app/cli/engine_check_command.h).
#include "app/cli/engine_check_command.h"
#include "metrics/measure_session.h"

#include <glm/vec4.hpp>

#include <vector>

namespace st::app {

// Returns the exit code: 0.
int writeEngineCheck(const EngineCheckOptions& opt, const xport::EngineKnobs& knobs, const metrics::PresetMeasurement& m,
                     const std::vector<glm::vec4>& engine, double seconds);

}  // namespace st::app
