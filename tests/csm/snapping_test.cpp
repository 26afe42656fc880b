// Texel snapping and sphere fit (seed 001): what keeps shadows from shimmering.
#include "renderer/csm/light_fit.h"
#include "renderer/csm/splits.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace st::csm {
namespace {

struct Rig {
    CameraParams cam;
    std::vector<float> splits;
    glm::vec3 wsLightDir = lightDirection(35.0f, 40.0f);
    FitParams fit;
    int cascade = 1;

    Rig() {
        cam.wsPosition = {12.3f, 4.56f, 31.7f};
        cam.wsTarget = {0.0f, 1.0f, 0.0f};
        SplitParams s;
        s.nearPlane = cam.nearPlane;
        s.farPlane = cam.farPlane;
        splits = computeSplits(s);
        fit.fit = FitMode::Sphere;
        fit.stabilize = true;
    }
    CascadeFit fitWith(const CameraParams& c) const {
        return fitCascade(c, splits, cascade, wsLightDir, fit);
    }
    CascadeFit fitMovedBy(glm::vec3 wsDelta) const {
        CameraParams c = cam;
        c.wsPosition += wsDelta;
        c.wsTarget += wsDelta;
        return fitWith(c);
    }
};

// (a - b) / texel, which must be a whole number of texels.
float texelsBetween(float a, float b, float texel) { return (a - b) / texel; }

TEST(SnappingTest, SubTexelMovesShiftTheBoxByZeroOrOneWholeTexel) {
    const Rig rig;
    const CascadeFit base = rig.fitWith(rig.cam);
    const float texel = base.texelWorldSize;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int moved = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
        const CascadeFit fit = rig.fitMovedBy(dir * (0.99f * texel * std::abs(u(rng))));
        EXPECT_NEAR(fit.texelWorldSize, texel, 1e-6f * texel);
        for (int axis = 0; axis < 2; ++axis) {
            EXPECT_NEAR(fit.lsBox.extent()[axis], base.lsBox.extent()[axis], 1e-3f * texel);
            const float onGrid = fit.lsBox.min[axis] / texel;
            EXPECT_NEAR(onGrid, std::round(onGrid), 1e-3f) << "min not on the texel grid";
            const float shift = texelsBetween(fit.lsBox.min[axis], base.lsBox.min[axis], texel);
            EXPECT_NEAR(shift, std::round(shift), 1e-3f);
            EXPECT_LE(std::abs(std::round(shift)), 1.0f);
            moved += std::round(shift) != 0.0f;
        }
    }
    EXPECT_GT(moved, 0) << "no move crossed a texel: the test would not see a bad snap";
}

TEST(SnappingTest, WholeTexelTranslationAlongLightXShiftsMinXByExactlyK) {
    const Rig rig;
    const CascadeFit base = rig.fitWith(rig.cam);
    const float texel = base.texelWorldSize;
    // ls x axis in ws: the first row of the light view's rotation.
    const glm::vec3 wsLightX(base.lsView[0][0], base.lsView[1][0], base.lsView[2][0]);
    for (int k : {1, 2, 3, 7, -1, -5, 40}) {
        const CascadeFit fit = rig.fitMovedBy(wsLightX * (static_cast<float>(k) * texel));
        EXPECT_NEAR(texelsBetween(fit.lsBox.min.x, base.lsBox.min.x, texel), k, 1e-3f) << k;
        EXPECT_NEAR(texelsBetween(fit.lsBox.min.y, base.lsBox.min.y, texel), 0.0f, 1e-3f) << k;
    }
}

CameraParams rotated(CameraParams c, float yawDeg, float pitchDeg) {
    const float yaw = glm::radians(yawDeg);
    const float pitch = glm::radians(pitchDeg);
    c.wsTarget = c.wsPosition + 10.0f * glm::vec3(std::cos(pitch) * std::cos(yaw), std::sin(pitch),
                                                  std::cos(pitch) * std::sin(yaw));
    return c;
}

TEST(SnappingTest, RotatingTheCameraInPlaceKeepsTheSphereBoxSize) {
    Rig rig;
    for (int stabilize = 0; stabilize < 2; ++stabilize) {
        rig.fit.stabilize = stabilize == 1;
        const glm::vec3 size = rig.fitWith(rig.cam).lsBox.extent();
        for (float yaw = 0.0f; yaw < 360.0f; yaw += 17.0f)
            for (float pitch : {-89.5f, -60.0f, -10.0f, 0.0f, 30.0f, 80.0f}) {
                const glm::vec3 s = rig.fitWith(rotated(rig.cam, yaw, pitch)).lsBox.extent();
                EXPECT_NEAR(s.x, size.x, 1e-5f * size.x) << yaw << " " << pitch;
                EXPECT_NEAR(s.y, size.y, 1e-5f * size.y) << yaw << " " << pitch;
            }
    }
}

TEST(SnappingTest, CascadeFitSizeDoesChangeWithRotationUnlikeSphere) {
    // Contrast for the test above: the tight crop box grows and shrinks as the camera turns
    // (seed 004), which is why the sphere fit exists.
    Rig rig;
    rig.fit.fit = FitMode::Cascade;
    float smallest = 1e30f;
    float largest = 0.0f;
    for (float yaw = 0.0f; yaw < 360.0f; yaw += 17.0f) {
        const float w = rig.fitWith(rotated(rig.cam, yaw, 0.0f)).lsBox.extent().x;
        smallest = std::min(smallest, w);
        largest = std::max(largest, w);
    }
    EXPECT_GT(largest, 1.05f * smallest);
}

// Where a fixed scene point falls in the map, in texels from the map's x,y origin, through the
// float matrix the shaders use (viewProj, scene -> clip): the fraction of a texel it lands at.
glm::vec2 texelPhase(const CascadeFit& fit, glm::vec3 scenePoint, int mapSize) {
    const glm::vec4 clip = fit.viewProj * glm::vec4(scenePoint, 1.0f);
    const glm::vec2 texels = (glm::vec2(clip) * 0.5f + 0.5f) * static_cast<float>(mapSize);
    return texels - glm::floor(texels);
}

// The largest change of that fraction over camera moves of up to a few texels: 0 when the box
// moves by whole texels of one grid (no shimmer), the mismatch of the grids otherwise.
float phaseDrift(const Rig& rig, glm::vec3 scenePoint) {
    const glm::vec2 base = texelPhase(rig.fitWith(rig.cam), scenePoint, rig.fit.mapSize);
    const float texel = rig.fitWith(rig.cam).texelWorldSize;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    float drift = 0.0f;
    for (int trial = 0; trial < 200; ++trial) {
        const glm::vec3 move(u(rng), 0.1f * u(rng), u(rng));
        const glm::vec2 d = glm::abs(texelPhase(rig.fitMovedBy(move * (4.0f * texel)), scenePoint, rig.fit.mapSize) - base);
        drift = std::max({drift, std::min(d.x, 1.0f - d.x), std::min(d.y, 1.0f - d.y)});
    }
    return drift;
}

TEST(SnappingTest, FiftyKilometresOutWorldLightSpaceLeavesTheGridAndCameraRelativeKeepsIt) {
    Rig rig;
    rig.cascade = 0;
    rig.fit.mapSize = 4096;  // 3.9 mm of float spacing 50 km out is then a large share of a texel
    const glm::vec3 point(1.3f, 0.2f, -2.7f);  // a scene point in cascade 0's slice
    const float atOrigin = phaseDrift(rig, point);
    rig.fit.wsOrigin = {50000.0f, 0.0f, 0.0f};
    const float world = phaseDrift(rig, point);
    rig.fit.cameraRelative = true;
    const float relative = phaseDrift(rig, point);
    rig.fit.wsOrigin = glm::vec3(0.0f);
    const float relativeAtOrigin = phaseDrift(rig, point);
    // At the origin the float error of the box is ~1e-5 of a texel; 50 km out in world light space
    // the box's coordinates are 3.9 mm apart in float, a sizeable share of cascade 0's texel.
    EXPECT_LT(atOrigin, 1e-3f);
    EXPECT_GT(world, 0.05f);
    EXPECT_LT(relative, 1e-3f);
    EXPECT_LT(relativeAtOrigin, 1e-3f);
}

TEST(SnappingTest, CameraRelativeBoxesCoverTheSameWorldAsWorldLightSpaceOnes) {
    // The same world box, whichever frame it is fitted in: map corners of the two fits at the
    // origin (where both are exact) land on the same scene points.
    Rig rig;
    const CascadeFit world = rig.fitWith(rig.cam);
    rig.fit.cameraRelative = true;
    const CascadeFit relative = rig.fitWith(rig.cam);
    EXPECT_NEAR(relative.texelWorldSize, world.texelWorldSize, 1e-6f * world.texelWorldSize);
    for (const glm::vec2 corner : {glm::vec2(-1.0f, -1.0f), glm::vec2(1.0f, 1.0f), glm::vec2(-1.0f, 1.0f)}) {
        const glm::vec4 clip(corner, 0.5f, 1.0f);
        const glm::vec3 a(glm::inverse(world.viewProj) * clip);
        const glm::vec3 b(glm::inverse(relative.viewProj) * clip);
        EXPECT_NEAR(glm::distance(a, b), 0.0f, 1e-3f * world.texelWorldSize + 1e-4f);
    }
}

TEST(SnappingTest, AFitFovKeepsTheSphereUnderAZoomBelowIt) {
    Rig rig;
    rig.cascade = 0;
    CameraParams wide = rig.cam;
    wide.fovY = glm::radians(70.0f);
    const float texelAt70 = rig.fitWith(wide).texelWorldSize;
    std::vector<float> free, fixed;
    for (float fov : {50.0f, 55.0f, 60.0f, 65.0f, 70.0f}) {
        CameraParams c = rig.cam;
        c.fovY = glm::radians(fov);
        rig.fit.minFovY = 0.0f;
        free.push_back(rig.fitWith(c).texelWorldSize);
        rig.fit.minFovY = glm::radians(70.0f);
        fixed.push_back(rig.fitWith(c).texelWorldSize);
        EXPECT_EQ(fixed.back(), texelAt70) << fov;
    }
    EXPECT_GT(free.back(), 1.2f * free.front()) << "the camera's FOV sizes the sphere";
    // Wider than the fit FOV, the camera's own FOV rules again.
    CameraParams wider = rig.cam;
    wider.fovY = glm::radians(80.0f);
    EXPECT_GT(rig.fitWith(wider).texelWorldSize, texelAt70);
}

}  // namespace
}  // namespace st::csm
