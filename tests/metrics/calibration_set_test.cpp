// `shadowtune calibrate`'s fixed set: every shipped preset it names loads and validates, and the
// set spans the work the sweeps ask for (sizes, map sizes, cascade counts, filters, depth bounds).
#include "app/calibration_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace st::app {
namespace {

TEST(CalibrationSetTest, SpansTheSweptKnobs) {
    const std::vector<CalibrationPoint> set = calibrationSet(ST_PRESET_DIR);
    ASSERT_GE(set.size(), 40u);
    std::set<std::string> names;
    std::set<int> mapSizes, counts, widths;
    bool depthBounds = false, moments = false, screenSpace = false, scene = false;
    for (const CalibrationPoint& p : set) {
        EXPECT_TRUE(names.insert(p.name).second) << "duplicate " << p.name;
        mapSizes.insert(p.settings.cascades.mapSize);
        counts.insert(p.settings.cascades.count);
        widths.insert(p.settings.output.width);
        depthBounds = depthBounds || p.settings.cascades.depthBounds == DepthBounds::Fit;
        moments = moments || p.settings.filter.kind == FilterKind::Vsm;
        screenSpace = screenSpace || p.settings.filter.screenSpace != ScreenSpace::Off;
        scene = scene || p.name.rfind("truck-town", 0) == 0;
    }
    EXPECT_TRUE(depthBounds);
    EXPECT_TRUE(moments);
    EXPECT_TRUE(screenSpace);
    EXPECT_TRUE(scene);
    for (int size : {512, 1024, 2048, 4096}) EXPECT_TRUE(mapSizes.count(size)) << size;
    for (int count : {1, 2, 3, 4}) EXPECT_TRUE(counts.count(count)) << count;
    EXPECT_TRUE(widths.count(320) && widths.count(640));
}

TEST(CalibrationSetTest, SizeOverridesEveryPoint) {
    for (const CalibrationPoint& p : calibrationSet(ST_PRESET_DIR, std::pair{64, 36})) {
        EXPECT_EQ(p.settings.output.width, 64) << p.name;
        EXPECT_EQ(p.settings.output.height, 36) << p.name;
    }
}

}  // namespace
}  // namespace st::app
