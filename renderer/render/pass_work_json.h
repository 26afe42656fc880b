#pragma once
// PassWork and FrameWork as JSON objects, keyed by their field names: the `work` of render's
// frame JSON and metrics.json's `cost.work`.
#include "renderer/render/pass_work.h"

#include <nlohmann/json.hpp>

namespace st {

nlohmann::ordered_json passWorkJson(const PassWork& w);
// {"shadow", "cascades": [...], "main", "filter", "depthBounds"}: pass -> counters.
nlohmann::ordered_json frameWorkJson(const FrameWork& w);

}  // namespace st
