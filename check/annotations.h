#pragma once
// GitHub Actions workflow commands for a check run's failures
// (`::error file=presets/a.json,title=shadowtune check: a::misclassified ...`), printed when
// GITHUB_ACTIONS is set so the failures show on the pull request. No GL.
#include "check/check_run.h"

#include <string>
#include <vector>

namespace st::check {

// One line per failing preset, escaped as the workflow-command syntax requires.
std::vector<std::string> githubAnnotations(const std::vector<PresetResult>& results);

}  // namespace st::check
