#include "app/cost_profile_file.h"

#include "app/preset_dir.h"
#include "metrics/cost_profile_json.h"

namespace st::app {
namespace fs = std::filesystem;

fs::path defaultCostProfileFor(const fs::path& presetDir) { return presetDir / "cost-profiles" / "llvmpipe.json"; }

fs::path defaultCostProfile() { return defaultCostProfileFor(defaultPresetDir()); }

metrics::CostProfile loadCostProfileOption(const fs::path& option) {
    return metrics::loadCostProfile(option.empty() ? defaultCostProfile() : option);
}

}  // namespace st::app
