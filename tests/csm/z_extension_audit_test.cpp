// The z-extension audit on a scene built so the answer is known: sun overhead (ls +Z is world
// +Y), a camera looking along -Z at 2 m, one tall box in its view.
#include "renderer/csm/frustum.h"
#include "renderer/csm/light_fit.h"
#include "renderer/csm/z_extension_audit.h"

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace st::csm {
namespace {

struct Fixture {
    CameraParams cam;
    std::vector<float> splits{1.0f, 20.0f};
    glm::vec3 dir = lightDirection(0.0f, 90.0f);
    // The slice's top is the far face's upper edge: y = 2 + 20 tan(30 deg).
    float sliceTop = 2.0f + 20.0f * std::tan(glm::radians(30.0f));
    Fixture() {
        cam.wsPosition = {0, 2, 0};
        cam.wsTarget = {0, 2, -10};
        cam.aspect = 1.0f;
        cam.fovY = glm::radians(60.0f);
        cam.nearPlane = 1.0f;
        cam.farPlane = 20.0f;
    }
    CascadeFit fit(ZExtension mode, float distance) const {
        FitParams p;
        p.zExtension = mode;
        p.zExtensionDistance = distance;
        p.wsSceneBounds = {{-1, 0, -10}, {1, 30, -8}};
        return fitCascade(cam, splits, 0, dir, p);
    }
};

const std::vector<Aabb> kCasters = {
    {{-1, 0, -10}, {1, 30, -8}},        // the tower: top 30 m
    {{-50, -0.1f, -50}, {50, 0, 50}},   // ground, inside the slice
    {{200, 0, 200}, {210, 80, 210}},    // taller but far outside the box in x,y
    {{-1, -60, -10}, {1, -40, -8}},     // under the slice: cannot shadow it
};

TEST(ZExtensionAuditTest, MinimalExtensionIsTheTowerTopAboveTheSlice) {
    const Fixture f;
    const ZExtensionAudit a = auditZExtension(f.fit(ZExtension::Distance, 5.0f), kCasters, ZExtension::Distance);
    const float expected = 30.0f - f.sliceTop;  // 16.45 m
    EXPECT_NEAR(a.minimal, expected, 1e-3f);
    EXPECT_NEAR(a.used, 5.0f, 1e-4f);
    EXPECT_TRUE(a.cuts);
    EXPECT_EQ(zExtensionWarning(2, a), "cascade 2: z-extension 5 m cuts casters up to 16.5 m toward the sun; "
                                       "minimal extension 16.5 m");
}

TEST(ZExtensionAuditTest, EnoughExtensionPancakeAndSceneBoundsCutNothing) {
    const Fixture f;
    const float expected = 30.0f - f.sliceTop;
    EXPECT_FALSE(auditZExtension(f.fit(ZExtension::Distance, expected + 0.01f), kCasters, ZExtension::Distance).cuts);
    const ZExtensionAudit pancake = auditZExtension(f.fit(ZExtension::Pancake, 0), kCasters, ZExtension::Pancake);
    EXPECT_FALSE(pancake.cuts);
    EXPECT_EQ(pancake.used, std::numeric_limits<float>::infinity());
    const ZExtensionAudit scene = auditZExtension(f.fit(ZExtension::SceneBounds, 0), kCasters, ZExtension::SceneBounds);
    EXPECT_NEAR(scene.used, expected, 1e-3f);
    EXPECT_FALSE(scene.cuts);
    EXPECT_TRUE(auditZExtension(f.fit(ZExtension::None, 0), kCasters, ZExtension::None).cuts);
}

TEST(ZExtensionAuditTest, CastersBelowTheSliceTopNeedNoExtension) {
    const Fixture f;
    const std::vector<Aabb> low = {{{-1, 0, -10}, {1, 3, -8}}};
    const ZExtensionAudit a = auditZExtension(f.fit(ZExtension::None, 0), low, ZExtension::None);
    EXPECT_EQ(a.minimal, 0.0f);
    EXPECT_FALSE(a.cuts);
}

TEST(ZExtensionAuditTest, MetresPrintWithOneDecimal) {
    EXPECT_EQ(formatMetres(152.0f), "152");
    EXPECT_EQ(formatMetres(0.25f), "0.2");  // round half to even of 0.25 in binary: 0.2
    EXPECT_EQ(formatMetres(16.4531f), "16.5");
}

}  // namespace
}  // namespace st::csm
