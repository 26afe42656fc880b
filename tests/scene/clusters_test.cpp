// Clusters (renderer/scene/clusters.h): every triangle once, bounded sizes, deterministic.
#include "renderer/scene/clusters.h"
#include "renderer/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <vector>

using namespace st;

namespace {
using Tri = std::array<std::uint32_t, 3>;

// A field of boxes of three materials plus a large ground: many small items and one big one.
Scene field(unsigned seed) {
    Scene s;
    s.materials.resize(3);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-50.0f, 50.0f);
    for (int i = 0; i < 300; ++i) {
        glm::vec3 p(u(rng), 0.0f, u(rng));
        addBox(s, p, p + glm::vec3(1.0f, 2.0f, 1.0f), i % 3);
    }
    addGroundQuad(s, 60.0f, 0.0f, 0);
    finalizeBounds(s);
    return s;
}

std::vector<Tri> trianglesOf(const std::vector<std::uint32_t>& indices) {
    std::vector<Tri> t;
    for (std::size_t i = 0; i + 3 <= indices.size(); i += 3) t.push_back({indices[i], indices[i + 1], indices[i + 2]});
    std::sort(t.begin(), t.end());
    return t;
}
}  // namespace

TEST(ClustersTest, HoldEveryTriangleOnceWithItsWindingInClustersOfOneMaterial) {
    const Scene s = field(1);
    const ClusteredScene c = buildClusters(s, 64);
    EXPECT_EQ(trianglesOf(c.indices), trianglesOf(s.indices));  // same triangles, same vertex order
    std::map<std::uint32_t, int> materialOfVertex;  // addBox gives each box its own vertices
    for (const DrawItem& d : s.draws)
        for (std::uint32_t i = d.firstIndex; i < d.firstIndex + d.indexCount; ++i) materialOfVertex[s.indices[i]] = d.material;
    std::uint32_t next = 0;
    int lastMaterial = -1;
    for (const Cluster& k : c.clusters) {
        EXPECT_EQ(k.firstIndex, next);  // contiguous, in order
        next += k.indexCount;
        EXPECT_GT(k.indexCount, 0u);
        EXPECT_LE(k.indexCount / 3, 64u);
        EXPECT_GE(k.material, lastMaterial);  // sorted by material
        lastMaterial = k.material;
        for (std::uint32_t i = k.firstIndex; i < k.firstIndex + k.indexCount; ++i) {
            EXPECT_EQ(materialOfVertex[c.indices[i]], k.material);
            EXPECT_TRUE(k.wsBounds.contains(s.vertices[c.indices[i]].position));
        }
    }
    EXPECT_EQ(next, c.indices.size());
}

TEST(ClustersTest, AreSpatial) {
    // 300 boxes over 100 m in clusters of 64 triangles (about 5 boxes): each cluster spans far
    // less than the field, or the split would not be spatial.
    const ClusteredScene c = buildClusters(field(2), 64);
    int small = 0;
    for (const Cluster& k : c.clusters) small += std::max(k.wsBounds.extent().x, k.wsBounds.extent().z) < 40.0f;
    EXPECT_GE(small, int(c.clusters.size()) - 3);  // all but the ground's
}

TEST(ClustersTest, AreTheSameEveryRun) {
    const Scene s = field(3);
    const ClusteredScene a = buildClusters(s);
    const ClusteredScene b = buildClusters(s);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.clusters.size(), b.clusters.size());
    for (std::size_t i = 0; i < a.clusters.size(); ++i) {
        EXPECT_EQ(a.clusters[i].firstIndex, b.clusters[i].firstIndex);
        EXPECT_EQ(a.clusters[i].indexCount, b.clusters[i].indexCount);
    }
    // Equal centroids (the same box twice) are ordered by scene index, not by memory or luck.
    Scene twins;
    twins.materials.resize(1);
    for (int i = 0; i < 100; ++i) addBox(twins, glm::vec3(0.0f), glm::vec3(1.0f), 0);
    finalizeBounds(twins);
    EXPECT_EQ(buildClusters(twins, 7).indices, buildClusters(twins, 7).indices);
}

TEST(ClustersTest, RejectsAZeroClusterSize) { EXPECT_THROW(buildClusters(field(4), 0), std::invalid_argument); }
