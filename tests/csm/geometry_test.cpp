#include "renderer/csm/geometry.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <random>

namespace st::csm {
namespace {

Corners cornersOf(const Aabb& b) {
    Corners c;
    for (std::size_t i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                (i & 4) ? b.max.z : b.min.z};
    return c;
}

TEST(GeometryTest, TransformAabbEqualsBruteForceForRandomAffineMatrices) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> coef(-2.0f, 2.0f);
    std::uniform_real_distribution<float> pos(-100.0f, 100.0f);
    for (int trial = 0; trial < 500; ++trial) {
        glm::mat4 m(1.0f);
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row) m[col][row] = coef(rng);
        m[3] = glm::vec4(pos(rng), pos(rng), pos(rng), 1.0f);
        const glm::vec3 a(pos(rng), pos(rng), pos(rng));
        const glm::vec3 b(pos(rng), pos(rng), pos(rng));
        const Aabb box{glm::min(a, b), glm::max(a, b)};

        Corners moved = cornersOf(box);
        for (glm::vec3& p : moved) p = glm::vec3(m * glm::vec4(p, 1.0f));
        const Aabb expected = boundsOf(moved);
        const Aabb actual = transformAabb(m, box);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(actual.min[k], expected.min[k], 1e-3f) << "trial " << trial;
            EXPECT_NEAR(actual.max[k], expected.max[k], 1e-3f) << "trial " << trial;
        }
    }
}

TEST(GeometryTest, BoundsOfAndContains) {
    const Aabb box = boundsOf(cornersOf({{-1, 2, -3}, {4, 5, 6}}));
    EXPECT_EQ(box.min, glm::vec3(-1, 2, -3));
    EXPECT_EQ(box.max, glm::vec3(4, 5, 6));
    EXPECT_TRUE(box.contains({4, 5, 6}));
    EXPECT_FALSE(box.contains({4.01f, 5, 6}));
    EXPECT_TRUE(box.contains({4.01f, 5, 6}, 0.02f));
    EXPECT_FALSE(box.contains({0, 1.9f, 0}));
}

}  // namespace
}  // namespace st::csm
