// Ray-cast ground truth on CPU scenes (Embree, no GL): occlusion, facing, alpha cut-outs and
// the start offset that keeps a surface from shadowing itself.
#include "metrics/ground_truth.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace st::metrics {
namespace {

const glm::vec3 kOverhead(0.0f, 1.0f, 0.0f);
const glm::vec3 kEye(0.0f, 5.0f, 10.0f);

TEST(GroundTruthTest, BoxShadowsTheGroundUnderIt) {
    const Scene scene = makeBuiltinScene("box-over-plane");  // box (-1,2,-1)..(1,4,1)
    const GroundTruth truth(scene);
    EXPECT_FALSE(truth.reachesSun({0.0f, 0.0f, 0.0f}, kOverhead));
    EXPECT_FALSE(truth.reachesSun({0.99f, 0.0f, -0.99f}, kOverhead));
    EXPECT_TRUE(truth.reachesSun({1.01f, 0.0f, 0.0f}, kOverhead));
    // A slanted sun moves the shadow away from it: the box's shadow starts 2 m / tan(45 deg) over.
    const glm::vec3 toSun = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    EXPECT_FALSE(truth.reachesSun({-2.5f, 0.0f, 0.0f}, toSun));
    EXPECT_TRUE(truth.reachesSun({0.5f, 0.0f, 0.0f}, toSun));
    EXPECT_GE(truth.buildMs(), 0.0);
}

TEST(GroundTruthTest, TraceMarksFacingAwayAndEmptyPixelsShadowed) {
    const Scene scene = makeBuiltinScene("box-over-plane");
    const GroundTruth truth(scene);
    MeasureSamples s = test::floorSamples(4, 1);
    s.position[0] = {0.0f, 0.0f, 0.0f, 1.0f};  // under the box
    s.position[1] = {3.0f, 0.0f, 0.0f, 1.0f};  // in the open
    s.position[2] = {3.0f, 0.0f, 0.0f, 0.0f};  // no surface
    s.position[3] = {3.0f, 0.0f, 0.0f, 1.0f};
    s.geometry[3].w = -0.5f;                     // its triangle faces away: no ray, shadowed
    EXPECT_EQ(truth.trace(s, kOverhead, kEye), (std::vector<std::uint8_t>{0, 1, 0, 0}));
    s.geometry[3].w = 1.0f;
    EXPECT_EQ(truth.trace(s, kOverhead, kEye)[3], 1);
}

// A ground quad and, 1 m above it, a MASK quad whose texture is transparent on its left texel.
Scene cutOutScene(bool mask) {
    Scene s;
    s.materials.push_back(Material{});
    Material leaf;
    leaf.baseColorTexture = 0;
    leaf.alphaMask = mask;
    s.materials.push_back(leaf);
    s.images.push_back(Image{2, 1, {255, 255, 255, 0, 255, 255, 255, 255}});
    addGroundQuad(s, 10.0f, 0.0f, 0);
    addGroundQuad(s, 1.0f, 1.0f, 1);  // uv = (x, z): texel 0 at x in (0, 0.5), texel 1 in (0.5, 1)
    finalizeBounds(s);
    return s;
}

TEST(GroundTruthTest, AlphaMaskedCastersLetLightThroughTheirHoles) {
    const Scene masked = cutOutScene(true);
    const GroundTruth truth(masked);
    EXPECT_TRUE(truth.reachesSun({0.2f, 0.0f, 0.3f}, kOverhead));   // under alpha 0
    EXPECT_FALSE(truth.reachesSun({0.8f, 0.0f, 0.3f}, kOverhead));  // under alpha 1
    const Scene opaque = cutOutScene(false);
    EXPECT_FALSE(GroundTruth(opaque).reachesSun({0.2f, 0.0f, 0.3f}, kOverhead));
}

TEST(GroundTruthTest, OffsetKeepsAFarSlantedSurfaceFromShadowingItself) {
    // A 2 km slope far from the origin: float positions on it sit a hair above or below.
    Scene s;
    s.materials.push_back(Material{});
    s.vertices = {{{900, 0, -900}}, {{1100, 0, -900}}, {{1100, 300, -1100}}, {{900, 300, -1100}}};
    s.indices = {0, 1, 2, 0, 2, 3};
    s.draws.push_back(DrawItem{0, 6, 0, {}});
    finalizeBounds(s);
    const GroundTruth truth(s);
    const glm::vec3 n = glm::normalize(glm::cross(glm::vec3(200, 0, 0), glm::vec3(0, 300, -200)));
    const glm::vec3 toSun = glm::normalize(n + glm::vec3(0.5f, 0.1f, 0.3f));
    ASSERT_GT(glm::dot(n, toSun), 0.1f);
    auto litCount = [&](RayOffset offset) {
        int lit = 0;
        for (int k = 0; k < 400; ++k) {
            const float u = float(k % 20) / 20.0f * 0.9f + 0.05f, v = float(k / 20) / 20.0f * 0.9f + 0.05f;
            const glm::vec3 p = glm::vec3(900, 0, -900) + u * glm::vec3(200, 0, 0) + v * glm::vec3(0, 300, -200);
            lit += truth.lit(p, n, toSun, glm::vec3(1000, 150, -800), offset);
        }
        return lit;
    };
    EXPECT_EQ(litCount(RayOffset{}), 400);
    EXPECT_LT(litCount(RayOffset{0.0f, 0.0f}), 400);  // without it, some points shadow themselves
}

}  // namespace
}  // namespace st::metrics
