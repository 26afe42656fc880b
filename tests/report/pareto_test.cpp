// paretoFront (report/pareto.h) on sets whose front is known by hand.
#include "report/pareto.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {
using st::report::paretoFront;
using Points = std::vector<std::pair<double, double>>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ParetoFrontTest, HandBuiltSet) {
    // (1,5) (2,3) (4,1) are the front; (3,4) is beaten by (2,3), (5,5) by all, (4,2) by (4,1).
    Points p{{3, 4}, {1, 5}, {5, 5}, {2, 3}, {4, 2}, {4, 1}};
    EXPECT_EQ(paretoFront(p), (std::vector<bool>{false, true, false, true, false, true}));
}

TEST(ParetoFrontTest, EqualPointsAreAllOnTheFront) {
    Points p{{2, 2}, {1, 3}, {2, 2}, {3, 3}, {2, 2}};
    EXPECT_EQ(paretoFront(p), (std::vector<bool>{true, true, true, false, true}));
}

TEST(ParetoFrontTest, EqualInOneCoordinateAndWorseInTheOtherIsDominated) {
    Points p{{1, 1}, {1, 2}, {2, 1}};
    EXPECT_EQ(paretoFront(p), (std::vector<bool>{true, false, false}));
}

TEST(ParetoFrontTest, SinglePointAndEmptySet) {
    EXPECT_EQ(paretoFront({{7, 9}}), std::vector<bool>{true});
    EXPECT_TRUE(paretoFront({}).empty());
}

TEST(ParetoFrontTest, NaNIsNeverOnTheFrontAndDominatesNothing) {
    Points p{{kNaN, 0}, {5, 5}, {0, kNaN}, {kNaN, kNaN}};
    EXPECT_EQ(paretoFront(p), (std::vector<bool>{false, true, false, false}));
}

TEST(ParetoFrontTest, PointsOnAFallingLineAreAllOnTheFront) {
    Points p;
    for (int i = 0; i < 10; ++i) p.emplace_back(i, 10 - i);
    EXPECT_EQ(paretoFront(p), std::vector<bool>(10, true));
}

TEST(ParetoFrontTest, PointsOnARisingLineLeaveOnlyTheFirst) {
    Points p;
    for (int i = 9; i >= 0; --i) p.emplace_back(i, 2.0 * i);
    std::vector<bool> expected(10, false);
    expected.back() = true;
    EXPECT_EQ(paretoFront(p), expected);
}

TEST(ParetoFrontTest, InfinityIsComparedLikeAnyValue) {
    double inf = std::numeric_limits<double>::infinity();
    Points p{{1, inf}, {2, 1}, {inf, 0}, {3, 3}};
    EXPECT_EQ(paretoFront(p), (std::vector<bool>{true, true, true, false}));
}

}  // namespace
