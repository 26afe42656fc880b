// Scenarios of presets/scenarios/ that must simply work: the sun straight overhead, the sun along
// a wall, an empty scene, a camera inside a caster. Finite figures, no throw, no GL error (the
// fixture fails on any serious debug message), and the shadows that are there are right.
#include "tests/metrics/scenario_gl_util.h"

#include <cmath>

namespace st {
namespace {

using test::printFigures;
using ScenarioGLTest = test::ScenarioGLTest;

bool finite(const metrics::ErrorCounts& e) { return std::isfinite(e.filteredError()) && std::isfinite(e.filteredAbsErrorSum); }
bool finite(const metrics::DensityStats& d) {
    return std::isfinite(d.median) && std::isfinite(d.p90) && std::isfinite(d.p95) && std::isfinite(d.max) &&
           std::isfinite(d.aliasingShare) && std::isfinite(d.wastedShare);
}

void expectFinite(const metrics::PresetMeasurement& m) {
    EXPECT_TRUE(finite(m.accuracy.all));
    EXPECT_TRUE(finite(m.density.all));
    for (const auto& c : m.accuracy.cascades) EXPECT_TRUE(finite(c));
    for (const auto& c : m.density.cascades) EXPECT_TRUE(finite(c));
}

// Receivers on the ground right under the 2 m box of box-over-plane (x, z in -0.9..0.9), and how
// many of them the unfiltered map test shadows.
struct UnderBox {
    std::size_t pixels = 0, truthShadowed = 0, mapShadowed = 0;
};
UnderBox underTheBox(const metrics::PresetMeasurement& m) {
    UnderBox u;
    for (std::size_t i = 0; i < m.samples.size(); ++i) {
        const glm::vec4 p = m.samples.position[i];
        if (!m.samples.receiver(i) || std::abs(p.y) > 1e-3f || std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;
        ++u.pixels;
        u.truthShadowed += m.truth[i] == 0;
        u.mapShadowed += m.samples.shadow[i].x < 0.5f;
    }
    return u;
}

TEST_F(ScenarioGLTest, SunOverheadGivesFiniteFiguresAndTheShadowUnderTheBox) {
    const metrics::PresetMeasurement m = measure("sun-overhead");
    const UnderBox u = underTheBox(m);
    printFigures("sun-overhead: %zu px under the box, truth shadowed %zu, map shadowed %zu; gross %zu of %zu",
                 u.pixels, u.truthShadowed, u.mapShadowed, m.accuracy.all.gross(), m.accuracy.all.receivers);
    expectFinite(m);
    ASSERT_GT(u.pixels, 100u);  // 154 at 320x180: the box hides most of its own shadow
    EXPECT_EQ(u.truthShadowed, u.pixels);  // the light falls straight down: the box covers it all
    EXPECT_EQ(u.mapShadowed, u.pixels);
    EXPECT_EQ(m.accuracy.all.gross(), 0u);
}

TEST_F(ScenarioGLTest, SunAlongAWallGivesFiniteFiguresAndNoGrossErrors) {
    const metrics::PresetMeasurement m = measure("sun-along-wall");
    printFigures("sun-along-wall: gross %zu, misclassified %zu of %zu receivers, facing away %zu",
                 m.accuracy.all.gross(), m.accuracy.all.misclassified(), m.accuracy.all.receivers, m.accuracy.facingAway);
    expectFinite(m);
    EXPECT_GT(m.accuracy.all.receivers, 20000u);
    EXPECT_EQ(m.accuracy.all.gross(), 0u);
}

TEST_F(ScenarioGLTest, EmptySceneMeasuresCleanlyWithNoReceivers) {
    metrics::MeasureOptions opt;
    opt.costFrames = 1;
    Settings s = test::scenario("empty-scene");
    const metrics::PresetMeasurement m = session_.measure(s, ST_PRESET_DIR, opt);
    expectFinite(m);
    EXPECT_EQ(m.accuracy.covered, 0u);
    EXPECT_EQ(m.accuracy.all.receivers, 0u);
    EXPECT_EQ(m.density.all.pixels, 0u);
    ASSERT_TRUE(m.cost.has_value());
    EXPECT_EQ(m.cost->sceneTriangles, 0u);
}

TEST_F(ScenarioGLTest, CameraInsideACasterMeasuresCleanly) {
    const metrics::PresetMeasurement m = measure("camera-inside-caster");
    printFigures("camera-inside-caster: covered %zu, receivers %zu, gross %zu", m.accuracy.covered,
                 m.accuracy.all.receivers, m.accuracy.all.gross());
    expectFinite(m);
    EXPECT_GT(m.accuracy.all.receivers, 10000u);  // the plane outside the box is seen
    EXPECT_EQ(m.accuracy.all.gross(), 0u);
}

}  // namespace
}  // namespace st
