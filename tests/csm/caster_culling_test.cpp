// Caster culling against the light box and the receivers' swept footprint
// (renderer/csm/caster_culling.h), on cases whose answer is known by construction.
#include "renderer/csm/cascade_plan.h"
#include "renderer/csm/caster_culling.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

using namespace st;
using namespace st::csm;

namespace {
// Sun straight overhead (light travels down), camera looking along -Z from z = 10 at height 2:
// the first slice's footprint on the ground is a trapezoid around x = 0 in front of the camera.
Settings overheadSettings() {
    Settings s;
    s.camera.position = {0.0f, 2.0f, 10.0f};
    s.camera.target = {0.0f, 2.0f, 0.0f};
    s.camera.farPlane = 100.0f;
    s.light.elevation = 89.0f;  // not exactly 90: keep the light view's up vector the usual one
    s.cascades.count = 2;
    s.cascades.zExtension = ZExtension::SceneBounds;
    return s;
}

struct Case {
    Settings s;
    CascadePlan plan;
};

Case plan(Settings s, Aabb scene) {
    return {s, planCascades(s, 16.0f / 9.0f, scene)};
}

CasterVolume volumeOf(const Case& c, int i) {
    return casterVolume(c.s, c.plan.camera, c.plan.splits, i, c.plan.cascades[std::size_t(i)]);
}
}  // namespace

TEST(CasterCullingTest, ConvexHullOfASquareWithInteriorPoints) {
    const auto h = convexHull({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.5f}, {0.5f, 0.0f}});
    ASSERT_EQ(h.size(), 4u);
    float area = 0.0f;  // shoelace: positive for counter-clockwise
    for (std::size_t i = 0; i < h.size(); ++i) area += h[i].x * h[(i + 1) % 4].y - h[(i + 1) % 4].x * h[i].y;
    EXPECT_FLOAT_EQ(area / 2.0f, 1.0f);
}

TEST(CasterCullingTest, FrustumPlanesKeepBoxesInsideAndDropBoxesBehindOrBeside) {
    CameraParams cam;  // at (0,0,5) looking at the origin, far 400
    const auto planes = frustumPlanes(projectionMatrix(cam) * viewMatrix(cam));
    EXPECT_TRUE(aabbInFrustum({{-1, -1, -1}, {1, 1, 1}}, planes));
    EXPECT_FALSE(aabbInFrustum({{-1, -1, 6}, {1, 1, 7}}, planes));        // behind the camera
    EXPECT_FALSE(aabbInFrustum({{100, -1, -1}, {101, 1, 1}}, planes));    // far to the side
    EXPECT_FALSE(aabbInFrustum({{-1, -1, -500}, {1, 1, -450}}, planes));  // past the far plane
    EXPECT_TRUE(aabbInFrustum({{-1000, -1, -10}, {1000, 1, -9}}, planes));// spans it
}

TEST(CasterCullingTest, SweptFootprintDropsCastersBesideTheSliceThatTheLightBoxKeeps) {
    // A sphere fit's box is the square around the slice's bounding circle; near the square's
    // corner, outside the circle and so outside the slice's footprint, a caster passes the box
    // test (the scene bounds extend the box in depth) but cannot shadow anything in the slice.
    Settings s = overheadSettings();
    s.cascades.fit = FitMode::Sphere;
    const Case c = plan(s, {{-200, -20, -200}, {200, 20, 200}});
    CasterVolume v = volumeOf(c, 0);
    const Aabb& box = v.lsBox;
    const glm::vec3 size = box.extent();
    const glm::mat4 wsFromLs = glm::inverse(v.lsView);
    auto casterAt = [&](glm::vec3 ls) {
        const glm::vec3 ws(wsFromLs * glm::vec4(ls, 1.0f));
        return Aabb{ws - 0.25f, ws + 0.25f};
    };
    const float midZ = box.center().z;
    const Aabb corner = casterAt({box.min.x + 0.02f * size.x, box.min.y + 0.02f * size.y, midZ});
    const Aabb centre = casterAt({box.center().x, box.center().y, box.max.z - 1.0f});
    ASSERT_TRUE(lsBoundsMeetBox(transformAabb(v.lsView, corner), box, false)) << "the box must keep it";
    EXPECT_FALSE(casterMayShadow(corner, v));
    EXPECT_TRUE(casterMayShadow(centre, v));
    v.sweep = false;  // cascades.casterCulling off: the box test alone
    EXPECT_TRUE(casterMayShadow(corner, v));
}

TEST(CasterCullingTest, KeepsCastersAboveTheSliceAndDropsThoseWhollyBelowIt) {
    Settings s = overheadSettings();
    const Case c = plan(s, {{-200, -50, -200}, {200, 300, 200}});
    const CasterVolume v = volumeOf(c, 0);
    EXPECT_TRUE(casterMayShadow({{-0.5f, 200, 6}, {0.5f, 201, 7}}, v));    // high above, toward the sun
    EXPECT_FALSE(casterMayShadow({{-0.5f, -40, 6}, {0.5f, -30, 7}}, v));   // under every receiver
}

TEST(CasterCullingTest, FilterTapsAndNormalOffsetWidenTheFootprint) {
    Settings s = overheadSettings();
    s.cascades.fit = FitMode::Sphere;
    Case c = plan(s, {{-200, 0, -200}, {200, 20, 200}});
    const float m0 = volumeOf(c, 0).margin;
    s.filter = {FilterKind::PcfNxN, 9};
    s.bias.normalOffset = 3.0f;
    c = plan(s, {{-200, 0, -200}, {200, 20, 200}});
    const float texel = c.plan.cascades[0].texelWorldSize;
    EXPECT_FLOAT_EQ(m0, 2.0f * texel);
    EXPECT_FLOAT_EQ(volumeOf(c, 0).margin, (4.0f + 2.0f + 3.0f) * texel);
}

TEST(CasterCullingTest, ReceiversOfAMapCoverTheBlendBandAndMapSelection) {
    Settings s = overheadSettings();
    s.cascades.count = 3;
    Case c = plan(s, {{-1, 0, -1}, {1, 1, 1}});
    const auto& sp = c.plan.splits;
    auto r = receiverDepthRange(s, sp, 1, c.plan.cascades[1]);
    EXPECT_EQ(r[0], sp[1]);
    EXPECT_EQ(r[1], sp[2]);
    s.cascades.blendBand = 0.1f;  // the far end of slice 0 blends into map 1
    r = receiverDepthRange(s, sp, 1, c.plan.cascades[1]);
    EXPECT_EQ(r[0], sp[0]);
    s.cascades.selection = Selection::Map;  // any pixel inside map 2's box reads it
    r = receiverDepthRange(s, sp, 2, c.plan.cascades[2]);
    EXPECT_EQ(r[0], sp[0]);
    EXPECT_EQ(r[1], sp[3]);
}
