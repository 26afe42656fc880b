// The Sweep panel's pure parts: axis text to a request (and every refusal's message), the
// chart's ticks and ranges, and which point the mouse picks.
#include "ui/pareto_plot.h"
#include "ui/sweep_axes.h"

#include <gtest/gtest.h>

using namespace st::ui;

namespace {
const std::vector<std::string> kSweepable = {"cascades.count", "cascades.mapSize", "cascades.lambda", "cascades.fit"};

std::string joined(const std::vector<std::string>& errors) {
    std::string all;
    for (const std::string& e : errors) all += e + "\n";
    return all;
}
}  // namespace

TEST(SweepAxesTest, ListsOfNumbersAndEnumNamesBecomeTheSweepFileValues) {
    ParsedAxis a = parseAxis({"cascades.count", false, "1, 2 4", 0, 0, 0}, kSweepable, "axis 1");
    ASSERT_TRUE(a.axis) << joined(a.errors);
    EXPECT_EQ(a.axis->values, nlohmann::json::parse("[1, 2, 4]"));
    EXPECT_EQ(a.count, 3u);
    ParsedAxis fit = parseAxis({"cascades.fit", false, "sphere, \"scene\"", 0, 0, 0}, kSweepable, "axis 2");
    ASSERT_TRUE(fit.axis) << joined(fit.errors);
    EXPECT_EQ(fit.axis->values, nlohmann::json::parse(R"(["sphere", "scene"])"));
}

TEST(SweepAxesTest, RangesCountLikeTheSweepReader) {
    ParsedAxis a = parseAxis({"cascades.lambda", true, "", 0.5, 0.95, 0.15}, kSweepable, "axis 1");
    ASSERT_TRUE(a.axis) << joined(a.errors);
    EXPECT_TRUE(a.axis->range);
    EXPECT_EQ(a.count, 4u);  // 0.5, 0.65, 0.8, 0.95
    EXPECT_DOUBLE_EQ(a.axis->values["step"].get<double>(), 0.15);
}

TEST(SweepAxesTest, RefusalsSayWhichAxisAndWhy) {
    auto errorsOf = [](AxisEdit e) { return joined(parseAxis(e, kSweepable, "axis 1").errors); };
    EXPECT_NE(errorsOf({"cascades.count", false, "1, 9", 0, 0, 0}).find("axis 1 (cascades.count)"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.count", false, "1, 9", 0, 0, 0}).find("value 2: must be in 1..8, got 9"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.count", false, "2, 2", 0, 0, 0}).find("twice"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.count", false, " , ", 0, 0, 0}).find("give values"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.fit", false, "round", 0, 0, 0}).find("round"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.fit", true, "", 0, 1, 1}).find("number field"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.lambda", true, "", 0.9, 0.1, 0.1}).find("step > 0 and to >= from"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.lambda", true, "", 0.0, 1.0, 0.001}).find("1001 values"), std::string::npos);
    EXPECT_NE(errorsOf({"scene", false, "builtin:yard", 0, 0, 0}).find("not a field a sweep can vary"), std::string::npos);
    EXPECT_NE(errorsOf({"cascades.lambda", true, "", 0.5, 1.5, 0.5}).find("cascades.lambda"), std::string::npos);  // 1.5 > max
}

TEST(SweepAxesTest, BothAxesTogether) {
    const AxisEdit count{"cascades.count", false, "1, 2", 0, 0, 0};
    ParsedSweep ok = parseSweep({count, {"cascades.mapSize", false, "512, 1024", 0, 0, 0}}, kSweepable, 320, 180);
    ASSERT_TRUE(ok.request) << joined(ok.errors);
    EXPECT_EQ(ok.points, 4u);
    EXPECT_EQ(ok.request->axes.size(), 2u);
    ParsedSweep one = parseSweep({count, {}}, kSweepable, 320, 180);  // axis 2 off
    ASSERT_TRUE(one.request);
    EXPECT_EQ(one.request->axes.size(), 1u);
    EXPECT_NE(joined(parseSweep({count, count}, kSweepable, 320, 180).errors).find("already the other axis"), std::string::npos);
    EXPECT_NE(joined(parseSweep({{}, {}}, kSweepable, 320, 180).errors).find("at least one axis"), std::string::npos);
    const AxisEdit many{"cascades.lambda", true, "", 0.0, 1.0, 0.005};  // 201 values
    EXPECT_NE(joined(parseSweep({many, count}, kSweepable, 320, 180).errors).find("402 points"), std::string::npos);
    EXPECT_NE(joined(parseSweep({count, {}}, kSweepable, 8, 180).errors).find("16x16"), std::string::npos);
}

TEST(ParetoPlotTest, NearestPointWithinTheRadius) {
    const std::vector<ImVec2> pts = {{10, 10}, {20, 10}, {100, 100}};
    EXPECT_EQ(nearestPoint(pts, {14, 10}, 10.0f), 0);
    EXPECT_EQ(nearestPoint(pts, {16, 11}, 10.0f), 1);
    EXPECT_EQ(nearestPoint(pts, {95, 97}, 10.0f), 2);
    EXPECT_EQ(nearestPoint(pts, {60, 60}, 10.0f), -1);   // nothing within 10 px
    EXPECT_EQ(nearestPoint({}, {0, 0}, 10.0f), -1);
}

TEST(ParetoPlotTest, TicksAreRoundAndInsideTheRange) {
    EXPECT_EQ(niceTicks(0.0, 1.0, 5), (std::vector<double>{0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0}));
    const std::vector<double> t = niceTicks(0.37, 4.2, 6);
    ASSERT_FALSE(t.empty());
    EXPECT_DOUBLE_EQ(t.front(), 1.0);  // step 1: 1, 2, 3, 4
    EXPECT_DOUBLE_EQ(t.back(), 4.0);
    EXPECT_EQ(niceTicks(5.0, 5.0, 4).size(), 1u);
}

TEST(ParetoPlotTest, MappingPutsTheRangeCornersOnThePlotCorners) {
    PlotMapping m{{100, 50}, {300, 250}, 0.0, 2.0, 0.0, 1.0};
    EXPECT_FLOAT_EQ(m.toScreen(0.0, 0.0).x, 100.0f);
    EXPECT_FLOAT_EQ(m.toScreen(0.0, 0.0).y, 250.0f);  // y up in data, down on screen
    EXPECT_FLOAT_EQ(m.toScreen(2.0, 1.0).x, 300.0f);
    EXPECT_FLOAT_EQ(m.toScreen(2.0, 1.0).y, 50.0f);
    const auto [lo, hi] = paddedRange({1.0, 3.0});
    EXPECT_DOUBLE_EQ(lo, 0.9);
    EXPECT_DOUBLE_EQ(hi, 3.1);
    const auto [l1, h1] = paddedRange({2.0});
    EXPECT_LT(l1, 2.0);
    EXPECT_GT(h1, 2.0);
}
