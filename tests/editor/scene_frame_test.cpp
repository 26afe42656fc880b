// Issue 13 #10: the editor reuses the scene image only while nothing it shows changed, and
// scales the image while the view moves so a moving frame keeps near its target time.
#include "app/editor/scene_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace st;
using namespace st::app;

namespace {
SceneFrameInputs baseInputs() {
    SceneFrameInputs in;
    in.sceneKey = "yard|ground";
    in.rendererGeneration = 1;
    in.live.output.width = 640;
    in.live.output.height = 360;
    in.pipWidth = 200, in.pipHeight = 120;
    return in;
}

FrameStats statsWith(bool redrawn, const std::string& reason) {
    FrameStats f;
    CascadeStats c;
    c.redrawn = redrawn;
    c.mapReason = reason;
    f.cascades = {CascadeStats{}, c};
    return f;
}
}  // namespace

TEST(SceneFrameCacheTest, ReusesOnlyTheSameInputs) {
    SceneFrameCache cache;
    const SceneFrameInputs held = baseInputs();
    EXPECT_EQ(cache.check(held), "first frame");
    const FrameStats stats = statsWith(false, "unchanged");
    cache.rendered(held, &stats, nullptr);
    EXPECT_EQ(cache.check(held), "") << "nothing changed: show the image held";

    // Every kind of change that feeds the image redraws it.
    const std::vector<std::pair<std::string, std::function<void(SceneFrameInputs&)>>> changes{
        {"a setting", [](SceneFrameInputs& in) { in.live.bias.slope += 0.25f; }},
        {"the camera", [](SceneFrameInputs& in) { in.live.camera.position.x += 0.01f; }},
        {"the sun (animated)", [](SceneFrameInputs& in) { in.live.light.azimuth += 0.5f; }},
        {"the debug view", [](SceneFrameInputs& in) { in.live.output.view = View::Cascades; }},
        {"the viewport size", [](SceneFrameInputs& in) { in.live.output.width = 641; }},
        {"the interactive scale", [](SceneFrameInputs& in) { in.live.output.height = 180; }},
        {"the maps (interactive)", [](SceneFrameInputs& in) { in.live = interactiveMaps(in.live); }},
        {"the scene", [](SceneFrameInputs& in) { in.sceneKey = "yard|no ground"; }},
        {"a reloaded renderer", [](SceneFrameInputs& in) { ++in.rendererGeneration; }},
        {"A of the split", [](SceneFrameInputs& in) { in.a = in.live; }},
        {"the side camera", [](SceneFrameInputs& in) { in.orbit.yawDeg += 1.0f; }},
        {"the side camera's pan", [](SceneFrameInputs& in) { in.orbit.panOffset.y += 1.0f; }},
        {"the side camera's zoom", [](SceneFrameInputs& in) { in.orbit.zoom *= 0.9f; }},
        {"the picture size", [](SceneFrameInputs& in) { in.pipWidth = 201; }},
        {"the view swap", [](SceneFrameInputs& in) { in.swapped = true; }},
    };
    for (const auto& [what, change] : changes) {
        SceneFrameInputs now = held;
        change(now);
        EXPECT_EQ(cache.check(now), "inputs changed") << what;
        EXPECT_FALSE(sameFrame(held, now)) << what;
    }
    SceneFrameInputs withA = held;
    withA.a = held.live;
    cache.rendered(withA, &stats, nullptr);
    SceneFrameInputs otherA = withA;
    otherA.a->bias.constant += 0.5f;
    EXPECT_EQ(cache.check(otherA), "inputs changed") << "A's own settings";
    cache.invalidate();
    EXPECT_EQ(cache.check(withA), "first frame");
}

TEST(SceneFrameCacheTest, AMapDeferredByItsIntervalIsDrawnInALaterFrame) {
    const FrameStats deferred = statsWith(false, "light matrix changed, deferred: update interval 3, drawn 1 frames ago");
    EXPECT_TRUE(mapsPending(deferred));
    EXPECT_FALSE(mapsPending(statsWith(false, "unchanged")));
    EXPECT_FALSE(mapsPending(statsWith(true, "light matrix changed")));
    SceneFrameCache cache;
    const SceneFrameInputs in = baseInputs();
    cache.rendered(in, &deferred, nullptr);
    EXPECT_EQ(cache.check(in), "a cascade's update interval is due");
    const FrameStats settled = statsWith(false, "unchanged");
    cache.rendered(in, &settled, &deferred);
    EXPECT_NE(cache.check(in), "") << "A's frame waits for a map too";
    cache.rendered(in, &settled, &settled);
    EXPECT_EQ(cache.check(in), "");
    cache.rendered(in, nullptr, nullptr);  // the settings failed: the same inputs fail again
    EXPECT_EQ(cache.check(in), "");
}

TEST(SceneFrameTest, OnlyTheCameraAndTheSunMoveTheView) {
    Settings a;
    Settings b = a;
    EXPECT_FALSE(viewMoving(a, b));
    b.bias.constant += 0.1f;
    EXPECT_FALSE(viewMoving(a, b)) << "a slider drag is judged at full resolution";
    b = a, b.camera.target.y += 0.1f;
    EXPECT_TRUE(viewMoving(a, b));
    b = a, b.light.azimuth += 1.0f;
    EXPECT_TRUE(viewMoving(a, b));
    b = a, b.light.elevation += 1.0f;
    EXPECT_TRUE(viewMoving(a, b));
}

TEST(SceneFrameTest, InteractiveMapsAreHalfTheirSizeAndFarOnesRedrawnLessOften) {
    Settings s;
    s.cascades.mapSize = 2048;
    s.cascades.mapSizes = {2048, 1024, 512, 256};
    const Settings m = interactiveMaps(s);
    EXPECT_EQ(m.cascades.mapSize, 1024);
    EXPECT_EQ(m.cascades.mapSizes, (std::vector<int>{1024, 512, 256, 256}));
    EXPECT_EQ(interactiveMaps(s, 4).cascades.mapSize, 512);
    EXPECT_EQ(interactiveMaps(s, 4).cascades.mapSizes, (std::vector<int>{512, 256, 256, 256}));
    s.cascades.count = 4;
    s.cascades.updateInterval = {1.0f, 1.0f, 5.0f};
    EXPECT_EQ(interactiveMaps(s).cascades.updateInterval, (std::vector<float>{1.0f, 2.0f, 5.0f, 4.0f}))
        << "cascade i every i + 1 frames at most, or the preset's longer interval";
    Settings rest = m;
    rest.cascades = s.cascades;
    EXPECT_EQ(rest, s) << "nothing but the maps changes";
    EXPECT_EQ(scaledSize(1280, 0.25), 320);
    EXPECT_EQ(scaledSize(40, 0.25), 16);
}

TEST(InteractiveScaleTest, FullResolutionWhenStillAndTheTargetTimeWhileMoving) {
    InteractiveScale scale(90.0);
    EXPECT_EQ(scale.update(false, 400.0), 1.0);
    EXPECT_EQ(scale.update(true, 400.0), 0.5) << "a still frame's time says nothing about a moving one";
    // A made-up fill-bound frame: 10 ms of panels plus 640 ms for the full viewport's pixels.
    auto frameMs = [](double k) { return 10.0 + 640.0 * k * k; };
    double k = 0.5;
    for (int i = 0; i < 12; ++i) k = scale.update(true, frameMs(k));
    EXPECT_NEAR(frameMs(k), 90.0, 0.15 * 90.0) << "settled at scale " << k;
    EXPECT_NEAR(std::fmod(k + 1e-9, InteractiveScale::kStep), 0.0, 1e-6) << "whole steps";
    const double settled = k;
    EXPECT_EQ(scale.update(true, frameMs(k)), settled) << "inside the band: no hunting";
    EXPECT_EQ(scale.update(false, frameMs(k)), 1.0) << "the gesture ended: full resolution the next frame";
    EXPECT_EQ(scale.update(true, 1000.0), settled) << "the next gesture starts where this one settled";
    EXPECT_EQ(scale.mapDivisor(), 2) << "half-size maps while the image scale can still give";
    for (int i = 0; i < 20; ++i) k = scale.update(true, 2000.0);
    EXPECT_EQ(k, InteractiveScale::kMin);
    EXPECT_EQ(scale.mapDivisor(), 4) << "the smallest image still too slow: quarter-size maps";
    for (int i = 0; i < 20; ++i) k = scale.update(true, 5.0);
    EXPECT_EQ(k, 1.0);
    EXPECT_EQ(scale.mapDivisor(), 2) << "full scale with time to spare: the maps grow back";
}

TEST(InteractiveScaleTest, QuarterMapsOnlyWhenTheSmallestImageMissesTheTarget) {
    // A made-up frame whose maps cost 120 ms at half size and 40 ms at quarter size, plus the
    // image's pixels: at the scale's floor the half-size maps alone miss 90 ms.
    InteractiveScale scale(90.0);
    auto frameMs = [&scale](double k) { return (scale.mapDivisor() == 2 ? 120.0 : 40.0) + 200.0 * k * k; };
    double k = scale.update(true, 0.0);
    for (int i = 0; i < 30; ++i) k = scale.update(true, frameMs(k));
    EXPECT_EQ(scale.mapDivisor(), 4);
    EXPECT_NEAR(frameMs(k), 90.0, 0.15 * 90.0) << "then the image scale settles on the target: " << k;
    EXPECT_GT(k, InteractiveScale::kMin);
}
