#pragma once
// results.json of a check run: per preset its status, message, image comparison and every
// repeatable figure with golden, actual, delta and (when checked) the rule and verdict. No GL.
#include "check/check_run.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace st::check {

struct RunInfo {
    std::string suite;     // the suite file
    std::string golden;    // the golden folder given
    std::string renderer;  // this run's
    std::string version;   // versionText()
    bool update = false;
};

nlohmann::ordered_json resultsJson(const RunInfo& info, const std::vector<PresetResult>& results);

}  // namespace st::check
