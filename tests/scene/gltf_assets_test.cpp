// The six third-party scenes of ../shared/assets (see its README.md): triangle counts ("drawn"
// column) and world bounds as the README gives them. Skipped where the folder is absent.
#include "tests/scene/gltf_test_builder.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>

namespace st::test {
namespace {

struct AssetCase {
    const char* file;  // relative to the assets folder
    std::size_t triangles;
    glm::vec3 wsMin;
    glm::vec3 wsMax;
};

// README bounds are rounded (to 0.1 m, or 1 m) and come from accessor min/max boxes transformed by
// node matrices (conservative: palm_tree_island's top is 3.83, not 4.2): the tolerance is 1% of
// the largest extent, at least 0.06 m.
const AssetCase kAssets[] = {
    {"truck_town/truck_town.gltf", 36'167, {-1024, -4.6f, -1024}, {1024, 23.6f, 1024}},
    {"palm_tree_island/PalmTree.gltf", 10'124, {-196, -1.0f, -196}, {196, 4.2f, 196}},
    {"zdm2_sauerbraten/zdm2.glb", 58'772, {-33.9f, -12.0f, -29.3f}, {43.3f, 24.0f, 30.3f}},
    {"dutch_ship/dutch_ship_medium_1k.gltf", 69'162, {-10.3f, -2.0f, -3.5f}, {13.7f, 22.7f, 3.3f}},
    {"living_room/living_room.glb", 5'088, {-5, -1.5f, -2.5f}, {5, 4, 12}},
    {"fox/Fox.glb", 576, {-12.6f, -0.1f, -88.1f}, {12.6f, 78.9f, 66.6f}},
};

void PrintTo(const AssetCase& c, std::ostream* os) { *os << c.file; }

class GltfAssetsTest : public ::testing::TestWithParam<AssetCase> {};

TEST_P(GltfAssetsTest, LoadsWithTheReadmeCountsAndBounds) {
    const fs::path assets = ST_SHARED_ASSETS_DIR;
    if (!fs::is_directory(assets)) GTEST_SKIP() << "no shared assets folder at " << assets << " (a user's own clone)";
    const AssetCase& c = GetParam();
    const auto start = std::chrono::steady_clock::now();
    const GltfLoadResult r = loadGltf(assets / c.file);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << "[ load     ] " << c.file << ": " << r.scene.triangleCount() << " triangles, " << r.scene.vertices.size()
              << " vertices, " << r.scene.draws.size() << " draws, " << r.scene.images.size() << " images in " << ms << " ms\n";
    for (const std::string& w : r.warnings) std::cout << "[ warning  ] " << w << '\n';
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(r.scene.triangleCount(), c.triangles);
    const glm::vec3 extent = c.wsMax - c.wsMin;
    const float tolerance = std::max(0.06f, 0.01f * std::max({extent.x, extent.y, extent.z}));
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(r.scene.wsBounds.min[i], c.wsMin[i], tolerance) << "axis " << i;
        EXPECT_NEAR(r.scene.wsBounds.max[i], c.wsMax[i], tolerance) << "axis " << i;
    }
    for (const DrawItem& d : r.scene.draws) {
        ASSERT_LT(d.material, static_cast<int>(r.scene.materials.size()));
        ASSERT_LE(std::size_t(d.firstIndex) + d.indexCount, r.scene.indices.size());
    }
    for (std::uint32_t index : r.scene.indices) ASSERT_LT(index, r.scene.vertices.size());
}

std::string assetName(const ::testing::TestParamInfo<AssetCase>& info) {
    std::string name = fs::path(info.param.file).stem().string();
    std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(SharedAssets, GltfAssetsTest, ::testing::ValuesIn(kAssets), assetName);

TEST(GltfAssetsDetailTest, SpecificFeatures) {
    const fs::path assets = ST_SHARED_ASSETS_DIR;
    if (!fs::is_directory(assets)) GTEST_SKIP() << "no shared assets folder at " << assets << " (a user's own clone)";
    // truck_town: the tree leaves are alpha-cut (MASK) and textured.
    const Scene town = loadGltf(assets / "truck_town/truck_town.gltf").scene;
    EXPECT_TRUE(std::any_of(town.materials.begin(), town.materials.end(),
                            [](const Material& m) { return m.alphaMask && m.baseColorTexture >= 0; }));
    EXPECT_EQ(town.images.size(), 5u);
    // zdm2 has no materials: every draw uses the one default material.
    const Scene zdm2 = loadGltf(assets / "zdm2_sauerbraten/zdm2.glb").scene;
    ASSERT_EQ(zdm2.materials.size(), 1u);
    // dutch_ship: only the three base colour JPEGs are decoded (not the normal or ARM maps).
    const Scene ship = loadGltf(assets / "dutch_ship/dutch_ship_medium_1k.gltf").scene;
    EXPECT_EQ(ship.images.size(), 3u);
    for (const Image& image : ship.images) EXPECT_EQ(image.rgba.size(), std::size_t(image.width) * image.height * 4);
    // palm_tree_island: the trunk node is mirrored (scale -1.56); every draw's winding must still
    // agree with its normals (a few authored normals may not: 97%).
    const Scene palm = loadGltf(assets / "palm_tree_island/PalmTree.gltf").scene;
    for (const DrawItem& d : palm.draws) {
        std::size_t agree = 0;
        for (std::uint32_t t = d.firstIndex; t < d.firstIndex + d.indexCount; t += 3) {
            const Vertex& a = palm.vertices[palm.indices[t]];
            const Vertex& b = palm.vertices[palm.indices[t + 1]];
            const Vertex& c = palm.vertices[palm.indices[t + 2]];
            const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
            if (glm::dot(n, a.normal + b.normal + c.normal) > 0.0f) ++agree;
        }
        EXPECT_GE(agree, 0.97 * d.indexCount / 3) << "draw with first index " << d.firstIndex;
    }
    // fox: no NORMAL, no indices: flat normals, three vertices per triangle.
    const Scene fox = loadGltf(assets / "fox/Fox.glb").scene;
    EXPECT_EQ(fox.vertices.size(), 3 * fox.triangleCount());
}

}  // namespace
}  // namespace st::test
