// sliceCornersThroughFloat32Inverse against the corners Babylon.js 9.28 itself reported for the same
// camera (engine-check on truck-town's view at 640x360, engines/babylon/page.js cascadeReport's
// sliceCornersWorld, Babylon's order turned into ours): the float32 stores are where the numbers
// differ from the exact slice, so matching Babylon to a micrometre and not the exact slice to a
// millimetre is the test that the arithmetic is Babylon's.
#include "renderer/csm/float32_corners.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>

namespace st::csm {
namespace {

// engine-check presets/scenes/truck-town.json --engine babylon --defaults (the job's camera).
Float32Camera truckTown() {
    return {{40.0, 14.0, 45.0}, {0.0, 2.0, 0.0}, 60.0, 640.0 / 360.0, 0.30000001192092896, 1500.0};
}

// Cascade 0 of Babylon's defaults there: break fractions 0 .. 0.1257410446452757 of [near, far].
// Babylon lists NDC (-1,+1) (+1,+1) (+1,-1) (-1,-1); Corners wants (-,-) (+,-) (+,+) (-,+).
const std::array<glm::dvec3, 8> kBabylonCascade0 = {
    glm::dvec3{39.59688837682335, 13.771497121165892, 45.009978410139055},
    glm::dvec3{40.05717208823936, 13.771497121523701, 44.600837331304355},
    glm::dvec3{40.01218749379696, 14.111224522745234, 44.55022966186645},
    glm::dvec3{39.5519037810102, 14.11122452756304, 44.95937074053945},
    glm::dvec3{-213.77422857950057, -129.85080491298393, 51.27983169590483},
    glm::dvec3{75.98805344858457, -129.83986613008452, -206.26996690863095},
    glm::dvec3{47.670856692896926, 84.01491155562553, -238.12898227266015},
    glm::dvec3{-242.09573356636474, 84.02023903640217, 19.42030790856929},
};

double farthest(const Corners& c) {
    double worst = 0.0;
    for (std::size_t k = 0; k < 8; ++k) worst = std::max(worst, glm::distance(glm::dvec3(c[k]), kBabylonCascade0[k]));
    return worst;
}

TEST(Float32CornersTest, MatchBabylonsOwnCornersTenTimesCloserThanTheExactSlice) {
    const Corners c = sliceCornersThroughFloat32Inverse(truckTown(), 0.0, 0.1257410446452757);
    // Not to the bit: Babylon's UniversalCamera rebuilds its view from rotation angles (its view's x
    // translation is -6.1e-7 where ours is 0), and the float32 inverse magnifies that to 1.4 mm at
    // the far corners, 5e-6 of their distance, 0.005 texel of a 2048 map.
    EXPECT_LT(farthest(c), 2e-3);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(glm::distance(glm::dvec3(c[k]), kBabylonCascade0[k]), 1e-5) << k;
}

TEST(Float32CornersTest, DifferFromTheExactSliceWhereBabylonDoes) {
    const Float32Camera cam = truckTown();
    CameraParams exact;
    exact.wsPosition = glm::vec3(cam.position);
    exact.wsTarget = glm::vec3(cam.target);
    exact.fovY = glm::radians(60.0f);
    exact.aspect = 640.0f / 360.0f;
    exact.nearPlane = float(cam.nearPlane);
    exact.farPlane = float(cam.farPlane);
    const float far0 = float(cam.nearPlane + 0.1257410446452757 * (cam.farPlane - cam.nearPlane));
    const Corners e = sliceCornersFromCamera(exact, exact.nearPlane, far0);
    // Far corners 290 m away moved by centimetres: 1e-4 of their distance, a tenth of a texel.
    std::printf("exact slice: %.4f m from Babylon's corners\n", farthest(e));
    EXPECT_GT(farthest(e), 2e-2);
    EXPECT_LT(farthest(e), 0.2);
}

TEST(Float32CornersTest, AModestDepthRangeKeepsTheExactSlice) {
    // far / near = 20: the float32 inverse is well conditioned and the corners are the exact ones.
    const Float32Camera cam{{0.0, 2.0, 5.0}, {0.0, 0.0, -5.0}, 50.0, 1.5, 1.0, 20.0};
    CameraParams exact;
    exact.wsPosition = glm::vec3(cam.position);
    exact.wsTarget = glm::vec3(cam.target);
    exact.fovY = glm::radians(50.0f);
    exact.aspect = 1.5f;
    exact.nearPlane = 1.0f;
    exact.farPlane = 20.0f;
    const Corners f = sliceCornersThroughFloat32Inverse(cam, 0.25, 0.75);
    const Corners e = sliceCornersFromCamera(exact, 1.0f + 0.25f * 19.0f, 1.0f + 0.75f * 19.0f);
    for (std::size_t k = 0; k < 8; ++k) EXPECT_LT(glm::distance(f[k], e[k]), 1e-4f) << k;
}

}  // namespace
}  // namespace st::csm
