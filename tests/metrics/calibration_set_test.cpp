// `shadowtune calibrate`'s fixed set: every shipped preset it names loads and validates, and the
// set spans the work the sweeps ask for (sizes, map sizes, cascade counts, filters, depth bounds).
#include "app/cli/calibration_set.h"
#include "renderer/csm/cascade_plan.h"
#include "sweep/sweep_spec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
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

// The depth-bounds pass is fitted on its own timers (metrics::fittedOnOwnTimers), so the set
// needs enough frames of it to tell its terms apart: several scenes (draws, primitives) and sizes
// (fragments, the reduction's invocations).
TEST(CalibrationSetTest, TimesTheDepthBoundsPassOnSeveralScenesAndSizes) {
    std::set<std::string> scenes;
    std::set<int> widths;
    for (const CalibrationPoint& p : calibrationSet(ST_PRESET_DIR)) {
        if (!csm::needsSampleBounds(p.settings.cascades)) continue;
        scenes.insert(p.name.substr(0, p.name.find(' ')));
        widths.insert(p.settings.output.width);
    }
    EXPECT_GE(scenes.size(), 6u);
    EXPECT_GE(widths.size(), 3u);
}

// scripts/bench_cost_model.sh judges the model on points 0, 7, 14, ... of the shipped sweeps
// (`calibrate --check --every 7`): a point the set fitted on must not be one of them.
TEST(CalibrationSetTest, TakesTheShippedSweepsPointsTheBenchDoesNotCheck) {
    const std::vector<CalibrationPoint> set = calibrationSet(ST_PRESET_DIR);
    const std::filesystem::path sweeps = std::filesystem::path(ST_PRESET_DIR) / "sweeps";
    std::size_t fromSweeps = 0;
    for (const auto& entry : std::filesystem::directory_iterator(sweeps)) {
        const sweep::SweepSpec spec = sweep::loadSweep(entry.path());
        const std::vector<sweep::Point> points = sweep::expandPoints(spec);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::string name = spec.name + " " + points[i].label;
            const bool inSet = std::any_of(set.begin(), set.end(), [&](const CalibrationPoint& p) {
                return p.name == name && p.settings == points[i].settings;
            });
            EXPECT_EQ(inSet, i >= kSweepFirst && (i - kSweepFirst) % kSweepEvery == 0) << name;
            if (i % 7 == 0) EXPECT_FALSE(inSet) << name << " is one the bench checks";
            fromSweeps += inSet;
        }
    }
    EXPECT_GE(fromSweeps, 30u);
}

TEST(CalibrationSetTest, SizeOverridesEveryPoint) {
    for (const CalibrationPoint& p : calibrationSet(ST_PRESET_DIR, std::pair{64, 36})) {
        EXPECT_EQ(p.settings.output.width, 64) << p.name;
        EXPECT_EQ(p.settings.output.height, 36) << p.name;
    }
}

}  // namespace
}  // namespace st::app
