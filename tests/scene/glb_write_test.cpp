// renderer/scene/glb_write.h: a scene's draws written as a .glb and read back by shadowtune's own
// glTF loader give the same triangles, materials and sidedness (what an engine's loader reads).
#include "renderer/scene/glb_write.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace st {
namespace {

std::filesystem::path writeTemp(const std::string& bytes, const char* name) {
    const auto file = std::filesystem::temp_directory_path() / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

TEST(GlbWriteTest, TheYardReadsBackTriangleForTriangle) {
    const Scene yard = loadScene("builtin:yard", ".");
    const auto file = writeTemp(glbOfDraws(yard), "st-glb-write-yard.glb");
    const Scene back = loadScene(file.string(), ".");
    ASSERT_EQ(back.triangleCount(), yard.triangleCount());
    ASSERT_EQ(back.draws.size(), yard.draws.size());
    for (std::size_t t = 0; t < yard.indices.size(); ++t) {
        const glm::vec3 a = yard.vertices[yard.indices[t]].position, b = back.vertices[back.indices[t]].position;
        ASSERT_NEAR(glm::distance(a, b), 0.0f, 1e-5f) << "index " << t;
    }
    for (std::size_t d = 0; d < yard.draws.size(); ++d) {
        const Material& m = yard.materials[std::size_t(yard.draws[d].material)];
        const Material& n = back.materials[std::size_t(back.draws[d].material)];
        EXPECT_EQ(m.doubleSided, n.doubleSided);
        EXPECT_EQ(m.alphaMask, n.alphaMask);
        EXPECT_NEAR(glm::distance(m.baseColor, n.baseColor), 0.0f, 1e-6f);
    }
    std::filesystem::remove(file);
}

TEST(GlbWriteTest, OnlyTheDrawsFromFirstDrawOnAreWritten) {
    Scene s = loadScene("builtin:box-over-plane", ".");
    const std::size_t first = s.draws.size();
    addGroundUnder(s);
    const auto file = writeTemp(glbOfDraws(s, first), "st-glb-write-ground.glb");
    const Scene ground = loadScene(file.string(), ".");
    EXPECT_EQ(ground.triangleCount(), 2u) << "the ground quad alone";
    EXPECT_NEAR(ground.wsBounds.max.y - ground.wsBounds.min.y, 0.0f, 1e-6f);
    EXPECT_NEAR(ground.wsBounds.min.y, s.wsBounds.min.y, 1e-5f);
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace st
