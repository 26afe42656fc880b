#include "tune/tune_holdout.h"

#include <gtest/gtest.h>

namespace st::tune {
namespace {

const HeldOutScore kInput{"input", 0.010, 0.012};

TEST(HeldOutVerdictTest, WithoutReferencesTheInputIsTheBaseline) {
    const HeldOutVerdict v = heldOutVerdict(kInput, {}, {"tuned", 0.006, 0.009});
    EXPECT_EQ(v.baseline, "input");
    EXPECT_DOUBLE_EQ(v.gainTuned, 0.004);
    EXPECT_DOUBLE_EQ(v.gainHeldOut, 0.003);
    EXPECT_TRUE(v.holds);  // keeps 3/4 of its gain
}

TEST(HeldOutVerdictTest, KeepingLessThanHalfTheGainIsFlagged) {
    EXPECT_FALSE(heldOutVerdict(kInput, {}, {"tuned", 0.006, 0.0111}).holds);  // keeps 0.0009 of 0.004
    EXPECT_TRUE(heldOutVerdict(kInput, {}, {"tuned", 0.006, 0.0099}).holds);   // keeps 0.0021
}

TEST(HeldOutVerdictTest, TheBestReferenceIsTheBaselineNotTheInput) {
    // The input is over the budget and better than anything within it; the references are not.
    const HeldOutScore input{"input", 0.004, 0.001};
    const std::vector<HeldOutScore> refs{{"unreal", 0.010, 0.011}, {"ogldev-49", 0.008, 0.009}};
    const HeldOutVerdict v = heldOutVerdict(input, refs, {"tuned", 0.005, 0.006});
    EXPECT_EQ(v.baseline, "ogldev-49");
    EXPECT_DOUBLE_EQ(v.gainTuned, 0.003);
    EXPECT_TRUE(v.holds);
    EXPECT_FALSE(heldOutVerdict(input, {}, {"tuned", 0.005, 0.006}).holds);  // against the input it would not
}

TEST(HeldOutVerdictTest, ALossMayNotGrowMoreThanTwofold) {
    const std::vector<HeldOutScore> refs{{"ogldev-49", 0.008, 0.008}};
    EXPECT_TRUE(heldOutVerdict(kInput, refs, {"tuned", 0.009, 0.0099}).holds);   // -0.001 -> -0.0019
    EXPECT_FALSE(heldOutVerdict(kInput, refs, {"tuned", 0.009, 0.0101}).holds);  // -0.001 -> -0.0021
}

TEST(HeldOutVerdictTest, NoGainMayNotTurnIntoALoss) {
    const std::vector<HeldOutScore> refs{{"ogldev-49", 0.008, 0.0}};
    EXPECT_TRUE(heldOutVerdict(kInput, refs, {"tuned", 0.008, 0.0}).holds);
    EXPECT_FALSE(heldOutVerdict(kInput, refs, {"tuned", 0.008, 0.0001}).holds);
}

// Held-out views with no error for either (nothing shadowed there) judge nothing: a tune that
// gained on its views is not flagged for keeping none of a gain the held-out views could not show.
TEST(HeldOutVerdictTest, HeldOutViewsWithoutErrorJudgeNothing) {
    const std::vector<HeldOutScore> refs{{"filament", 0.2154, 0.0}};
    const HeldOutVerdict v = heldOutVerdict(kInput, refs, {"tuned", 0.1564, 0.0});
    EXPECT_FALSE(v.judged);
    EXPECT_TRUE(v.holds);
    const HeldOutVerdict lost = heldOutVerdict(kInput, refs, {"tuned", 0.1564, 0.0001});
    EXPECT_TRUE(lost.judged);
    EXPECT_FALSE(lost.holds) << "an error where the baseline had none is judged, and lost";
}

}  // namespace
}  // namespace st::tune
