// metrics/seams.h on synthetic samples: the band follows cascade changes, the jump counts what
// changes across it.
#include "metrics/seams.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

namespace st {
namespace {

// 8x6 floor: rows 0-2 in cascade 0, rows 3-5 in cascade 1.
MeasureSamples twoCascades() {
    MeasureSamples s = test::floorSamples(8, 6);
    for (int y = 3; y < 6; ++y)
        for (int x = 0; x < 8; ++x) s.shadow[std::size_t(y * 8 + x)].z = 1.0f;
    return s;
}

TEST(SeamsTest, BandIsTheRowsAroundTheCascadeChange) {
    const MeasureSamples s = twoCascades();
    const std::vector<std::uint8_t> band = metrics::seamBand(s, std::vector<std::uint8_t>(s.size(), 1), 1);
    for (int y = 0; y < 6; ++y)
        EXPECT_EQ(band[std::size_t(y * 8)], (y >= 1 && y <= 4) ? 1 : 0) << "row " << y;
}

TEST(SeamsTest, NoCascadeChangeNoBand) {
    const MeasureSamples s = test::floorSamples(8, 6);
    const metrics::SeamReport r = metrics::measureSeams(s, std::vector<std::uint8_t>(s.size(), 1), 2);
    EXPECT_EQ(r.bandPixels, 0u);
    EXPECT_EQ(r.meanAbsJump, 0.0);
}

TEST(SeamsTest, AJumpAcrossTheSplitIsCountedAndAnErrorToo) {
    MeasureSamples s = twoCascades();
    for (int x = 0; x < 8; ++x)
        for (int y = 3; y < 6; ++y) test::setMap(s, x, y, 1.0f, 0.5f);  // cascade 1 says half lit
    const metrics::SeamReport r = metrics::measureSeams(s, std::vector<std::uint8_t>(s.size(), 1), 1);
    EXPECT_EQ(r.bandPixels, 32u);  // rows 1-4
    EXPECT_DOUBLE_EQ(r.meanAbsError, 0.25);  // half the band at |0.5 - 1|
    EXPECT_EQ(r.pairs, 8u);                  // the vertical pairs of rows 2-3
    EXPECT_DOUBLE_EQ(r.meanAbsJump, 0.5);
}

TEST(SeamsTest, AChangeAwayFromTheSplitIsNoJump) {
    MeasureSamples s = twoCascades();
    for (int x = 0; x < 4; ++x) test::setMap(s, x, 1, 1.0f, 0.0f);  // a shadow edge along a row in cascade 0
    EXPECT_EQ(metrics::measureSeams(s, std::vector<std::uint8_t>(s.size(), 1), 1).meanAbsJump, 0.0);
}

TEST(SeamsTest, ATrueShadowEdgeOnTheSplitIsNoSeam) {
    MeasureSamples s = twoCascades();
    std::vector<std::uint8_t> truth(s.size(), 1);
    for (int x = 0; x < 8; ++x)
        for (int y = 3; y < 6; ++y) {
            test::setMap(s, x, y, 0.0f, 0.0f);
            truth[std::size_t(y * 8 + x)] = 0;  // the map is right: cascade 1's rows are in shadow
        }
    const metrics::SeamReport r = metrics::measureSeams(s, truth, 1);
    EXPECT_EQ(r.pairs, 0u);
    EXPECT_EQ(r.bandPixels, 0u);
}

}  // namespace
}  // namespace st
