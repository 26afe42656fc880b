// The shipped cost profile: where it is found, and that it is a valid profile of llvmpipe that
// models every pass kind a sweep meets (what the default --profile loads).
#include "app/cost_profile_file.h"
#include "metrics/cost_profile_json.h"

#include <gtest/gtest.h>

namespace st::app {
namespace {

TEST(CostProfileFileTest, DefaultIsBesideThePresets) {
    EXPECT_EQ(defaultCostProfileFor("/usr/share/shadowtune/presets"),
              std::filesystem::path("/usr/share/shadowtune/presets/cost-profiles/llvmpipe.json"));
}

TEST(CostProfileFileTest, ShippedLlvmpipeProfileLoads) {
    const metrics::CostProfile p = loadCostProfileOption(defaultCostProfileFor(ST_PRESET_DIR));
    EXPECT_EQ(p.renderer.rfind("llvmpipe", 0), 0u) << p.renderer;
    for (metrics::PassKind k : metrics::kPassKinds) {
        EXPECT_FALSE(p.pass(k).terms.empty()) << metrics::passKindName(k);
        EXPECT_GT(p.pass(k).samples, 0) << metrics::passKindName(k);
    }
    EXPECT_FALSE(p.residuals.empty());
}

TEST(CostProfileFileTest, ProfileOptionErrorsNameTheFile) {
    try {
        loadCostProfileOption("/nonexistent/p.json");
        FAIL() << "no error";
    } catch (const metrics::CostProfileError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/p.json"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace st::app

namespace st::app {
namespace {

// The compiled-in default is the shipped file, whatever folder a command runs from.
TEST(CostProfileFileTest, EmptyOptionIsTheCompiledInShippedProfile) {
    EXPECT_EQ(loadCostProfileOption(""), loadCostProfileOption(defaultCostProfileFor(ST_PRESET_DIR)));
}

}  // namespace
}  // namespace st::app
