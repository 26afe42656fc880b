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

}  // namespace
}  // namespace st::csm
