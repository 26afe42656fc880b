// bias.normalOffsetSide "caster-sin" (Babylon.js shadowMapVertexNormalBias.js): the shadow pass moves
// each caster into its surface by normalOffset x sin(N, L). Known answer on the box-over-plane's
// ground (normal +Y, sun at elevation e, so sin(N, L) = cos e): the ground sinks by d cos e, which
// the light sees as d cos e / sin e = d / tan e metres farther along its ray; every ground texel's
// stored depth grows by that over the box's depth range. Receivers are not moved (their offset 0).
#include "renderer/render/shadow_maps.h"
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace st;

namespace {
class CasterOffsetGLTest : public test::GLTest {};

TEST_F(CasterOffsetGLTest, TheGroundSinksByTheOffsetTimesSinAlongItsNormal) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = test::boxOverPlaneView({0.0f, 12.0f, 14.0f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    s.light.azimuth = 30.0f;
    s.light.elevation = 40.0f;
    s.cascades.count = 1;
    s.cascades.mapSize = 256;
    s.cascades.stabilize = false;
    s.cascades.zExtension = ZExtension::SceneBounds;
    s.output = {64, 48, View::Shaded};
    s.bias.normalOffsetUnit = OffsetUnit::Metres;
    s.bias.normalOffsetSide = NormalOffsetSide::CasterSin;
    s.bias.normalOffset = 0.0f;
    r.render(s);
    const std::vector<float> before = readCascadeDepth(r.shadowMaps(), 0);
    const csm::Aabb box = r.plan().cascades[0].lsBox;
    s.bias.normalOffset = 0.25f;
    r.render(s);
    ASSERT_EQ(r.plan().cascades[0].lsBox.min.z, box.min.z);  // the same box: depths compare directly
    const std::vector<float> after = readCascadeDepth(r.shadowMaps(), 0);
    const double e = glm::radians(40.0);
    const double want = 0.25 / std::tan(e) / double(box.max.z - box.min.z);  // in the map's depth units
    int covered = 0, ground = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
        if (before[i] >= 1.0f) continue;  // no caster: the clear value
        ++covered;
        ground += std::abs(double(after[i]) - double(before[i]) - want) < 1e-3 * want;
    }
    // The ground covers most texels that hold a caster (the box's faces move by other amounts).
    EXPECT_GT(covered, 1000);
    EXPECT_GT(ground, covered * 8 / 10) << "want a depth step of " << want;
}

}  // namespace
