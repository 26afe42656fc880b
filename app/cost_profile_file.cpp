#include "app/cost_profile_file.h"

#include "metrics/cost_profile_json.h"

#include <cstdio>
#include <string>

namespace st::app {
namespace fs = std::filesystem;

fs::path defaultCostProfileFor(const fs::path& presetDir) { return presetDir / "cost-profiles" / "llvmpipe.json"; }

metrics::CostProfile loadCostProfileOption(const fs::path& option) {
    if (!option.empty()) return metrics::loadCostProfile(option);
    const std::string name = "built-in presets/cost-profiles/llvmpipe.json";
    nlohmann::ordered_json root;
    try {
        root = nlohmann::ordered_json::parse(defaultCostProfileText());
    } catch (const nlohmann::json::exception& e) {
        throw metrics::CostProfileError(name, "(top level)", e.what());
    }
    return metrics::costProfileFromJson(root, name);
}

std::shared_ptr<const metrics::CostProfile> loadCostProfileOrReport(const fs::path& option) {
    try {
        return std::make_shared<const metrics::CostProfile>(loadCostProfileOption(option));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return nullptr;
    }
}

}  // namespace st::app
