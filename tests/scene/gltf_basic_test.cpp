// What a valid file turns into: vertices, indices, normals, winding, transforms, materials.
#include "tests/scene/gltf_test_builder.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace st::test {
namespace {

glm::vec3 geometricNormal(const Scene& s, std::size_t triangle) {
    const glm::vec3 a = s.vertices[s.indices[3 * triangle]].position;
    const glm::vec3 b = s.vertices[s.indices[3 * triangle + 1]].position;
    const glm::vec3 c = s.vertices[s.indices[3 * triangle + 2]].position;
    return glm::normalize(glm::cross(b - a, c - a));
}

// Every triangle's stored normals point the way its counter-clockwise winding does.
void expectWindingMatchesNormals(const Scene& s) {
    for (std::size_t t = 0; t < s.triangleCount(); ++t) {
        const glm::vec3 n = geometricNormal(s, t);
        for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(n, s.vertices[s.indices[3 * t + k]].normal), 0.99f) << "triangle " << t;
    }
}

void expectNear(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(GltfLoadTest, TriangleWithDataUri) {
    TempDir dir;
    const GltfLoadResult r = loadGltf(triangleBuilder().writeDataUri(dir / "tri.gltf"));
    const Scene& s = r.scene;
    EXPECT_EQ(s.name, "tri");
    ASSERT_EQ(s.triangleCount(), 1u);
    ASSERT_EQ(s.vertices.size(), 3u);
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].indexCount, 3u);
    expectNear(s.vertices[1].position, {1, 0, 0});
    expectNear(s.vertices[2].normal, {0, 0, 1});
    expectNear(s.wsBounds.min, {0, 0, 0});
    expectNear(s.wsBounds.max, {1, 1, 0});
    expectNear(s.draws[0].wsBounds.max, {1, 1, 0});
    ASSERT_EQ(s.materials.size(), 1u);  // the default material
    EXPECT_EQ(s.draws[0].material, 0);
    EXPECT_TRUE(r.warnings.empty());
    expectWindingMatchesNormals(s);
}

// Settings::ground: a quad under the lowest point, centred, 4x the larger horizontal extent,
// facing up, as one extra draw with its own material; the scene bounds grow to hold it.
TEST(GltfLoadTest, GroundOptionAddsAQuadUnderTheScene) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeDataUri(dir / "tri.gltf");  // (0,0,0) (1,0,0) (0,1,0)
    const Scene plain = loadScene(file.string(), dir.path());
    const Scene s = loadScene(file.string(), dir.path(), SceneOptions{.ground = true});
    ASSERT_EQ(s.draws.size(), plain.draws.size() + 1);
    ASSERT_EQ(s.triangleCount(), plain.triangleCount() + 2);
    EXPECT_EQ(s.draws.back().material, int(plain.materials.size()));
    expectNear(s.draws.back().wsBounds.min, {0.5f - 2.0f, 0.0f, -2.0f});
    expectNear(s.draws.back().wsBounds.max, {0.5f + 2.0f, 0.0f, 2.0f});
    expectNear(s.wsBounds.max, {2.5f, 1.0f, 2.0f});
    for (std::size_t t = plain.triangleCount(); t < s.triangleCount(); ++t) expectNear(geometricNormal(s, t), {0, 1, 0});
    EXPECT_NE(sceneKey(file.string(), dir.path(), {.ground = true}), sceneKey(file.string(), dir.path()));
}

class GltfIndexTypeTest : public ::testing::TestWithParam<int> {};

TEST_P(GltfIndexTypeTest, QuadReadsEveryIndexType) {
    TempDir dir;
    GltfBuilder b;
    const int pos = b.addVec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const int idx = b.addIndices({0, 1, 2, 0, 2, 3}, GetParam());
    b.addMesh(Json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}}));
    b.setScene({b.addNode({{"mesh", 0}})});
    const Scene s = loadGltf(b.writeGlb(dir / "quad.glb")).scene;
    ASSERT_EQ(s.triangleCount(), 2u);
    expectNear(s.vertices[s.indices[2]].position, {1, 1, 0});
    expectNear(s.vertices[s.indices[5]].position, {0, 1, 0});
    expectWindingMatchesNormals(s);  // no NORMAL: flat, +Z
}

INSTANTIATE_TEST_SUITE_P(IndexTypes, GltfIndexTypeTest, ::testing::Values(kU8, kU16, kU32));

TEST(GltfLoadTest, NonIndexedWithoutNormalsGetsFlatNormals) {
    TempDir dir;
    const Scene s = loadGltf(triangleBuilder(false, false).writeDataUri(dir / "flat.gltf")).scene;
    ASSERT_EQ(s.triangleCount(), 1u);
    ASSERT_EQ(s.vertices.size(), 3u);
    for (const Vertex& v : s.vertices) expectNear(v.normal, {0, 0, 1});
}

TEST(GltfLoadTest, IndexedWithoutNormalsDuplicatesVerticesPerTriangle) {
    TempDir dir;
    GltfBuilder b;
    // Two triangles sharing an edge at a right angle: shared vertices must not share normals.
    const int pos = b.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}});
    const int idx = b.addIndices({0, 1, 2, 0, 3, 1}, kU16);
    b.addMesh(Json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}}));
    b.setScene({b.addNode({{"mesh", 0}})});
    const Scene s = loadGltf(b.writeDataUri(dir / "fold.gltf")).scene;
    ASSERT_EQ(s.vertices.size(), 6u);
    expectNear(s.vertices[0].normal, {0, 0, 1});
    expectNear(s.vertices[3].normal, {0, -1, 0});
    expectWindingMatchesNormals(s);
}

TEST(GltfLoadTest, NegativeScaleFlipsWinding) {
    for (bool withNormals : {true, false}) {
        TempDir dir;
        GltfBuilder b = triangleBuilder(withNormals);
        b.doc["nodes"][0]["scale"] = {-1.0, 1.0, 1.0};
        const Scene s = loadGltf(b.writeDataUri(dir / "mirror.gltf")).scene;
        ASSERT_EQ(s.triangleCount(), 1u);
        // Mirrored in x the triangle still faces +Z, and reads counter-clockwise from there.
        expectNear(geometricNormal(s, 0), {0, 0, 1});
        expectNear(s.vertices[0].normal, {0, 0, 1});
        expectWindingMatchesNormals(s);
    }
}

TEST(GltfLoadTest, NormalsUseInverseTransposeAndAreNormalized) {
    TempDir dir;
    GltfBuilder b;
    // A 45-degree slope; non-uniform scale 4 in x must tilt its normal towards +y.
    const int pos = b.addVec3({{0, 0, 0}, {1, 1, 0}, {0, 0, -1}});
    const glm::vec3 n = glm::normalize(glm::vec3(-1, 1, 0));
    const int nrm = b.addVec3({n, n, n});
    b.addMesh(Json::array({{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}}}));
    b.setScene({b.addNode({{"mesh", 0}, {"scale", {4.0, 1.0, 1.0}}})});
    const Scene s = loadGltf(b.writeDataUri(dir / "slope.gltf")).scene;
    expectNear(s.vertices[0].normal, glm::normalize(glm::vec3(-0.25f, 1.0f, 0.0f)));
    expectWindingMatchesNormals(s);
}

TEST(GltfLoadTest, TrsAndMatrixGiveTheSameVertices) {
    TempDir dir;
    // Parent: translation (5, 0, -2); child: 90 degrees about +Y, scale 2.
    GltfBuilder trs = triangleBuilder();
    trs.doc["nodes"][0] = {{"children", {1}}, {"translation", {5.0, 0.0, -2.0}}};
    const double h = std::sqrt(0.5);
    trs.addNode({{"mesh", 0}, {"rotation", {0.0, h, 0.0, h}}, {"scale", {2.0, 2.0, 2.0}}});
    GltfBuilder mat = triangleBuilder();
    // Column-major T * R * S: x -> -2z, y -> 2y, z -> 2x, plus the translation.
    mat.doc["nodes"][0] = {{"matrix", {0, 0, -2, 0, 0, 2, 0, 0, 2, 0, 0, 0, 5, 0, -2, 1}}, {"mesh", 0}};
    const Scene a = loadGltf(trs.writeDataUri(dir / "trs.gltf")).scene;
    const Scene c = loadGltf(mat.writeDataUri(dir / "matrix.gltf")).scene;
    ASSERT_EQ(a.vertices.size(), c.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
        expectNear(a.vertices[i].position, c.vertices[i].position);
        expectNear(a.vertices[i].normal, c.vertices[i].normal);
    }
    expectNear(a.vertices[1].position, {5, 0, -4});
    expectNear(a.vertices[0].normal, {1, 0, 0});
}

TEST(GltfLoadTest, MaskMaterialAndBaseColor) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.addMaterial({{"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true},
                   {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 0.8}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene s = loadGltf(b.writeDataUri(dir / "mask.gltf")).scene;
    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_TRUE(m.alphaMask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_FLOAT_EQ(m.baseColor.y, 0.4f);
    EXPECT_FLOAT_EQ(m.baseColor.w, 0.8f);
    EXPECT_EQ(m.baseColorTexture, -1);
}

TEST(GltfLoadTest, BaseColorTextureIsDecodedToRgba8) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    const std::vector<std::uint8_t> rgba = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 10, 20, 30, 40};
    const std::vector<std::uint8_t> png = encodePng(2, 2, rgba);
    b.doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(png)}}});
    b.doc["textures"] = Json::array({{{"source", 0}}});
    b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addVec2({{0, 0}, {1, 0}, {0, 1}});
    const Scene s = loadGltf(b.writeDataUri(dir / "textured.gltf")).scene;
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].width, 2);
    EXPECT_EQ(s.images[0].rgba, rgba);
    EXPECT_EQ(s.materials[0].baseColorTexture, 0);
    EXPECT_FLOAT_EQ(s.vertices[1].uv.x, 1.0f);
}

TEST(GltfLoadTest, NormalizedU16TexcoordsAreScaled) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    const std::uint16_t uv[6] = {0, 0, 65535, 0, 0, 32768};
    const int acc = b.addAccessor(b.addView(uv, sizeof(uv)), kU16, 3, "VEC2");
    b.doc["accessors"][acc]["normalized"] = true;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = acc;
    const Scene s = loadGltf(b.writeDataUri(dir / "uv16.gltf")).scene;
    EXPECT_FLOAT_EQ(s.vertices[1].uv.x, 1.0f);
    EXPECT_NEAR(s.vertices[2].uv.y, 0.5f, 1e-4f);
}

TEST(GltfLoadTest, OneDrawPerPrimitiveInstance) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    Json second = b.doc["meshes"][0]["primitives"][0];
    second["material"] = b.addMaterial({{"doubleSided", true}});
    b.addMaterial({{"doubleSided", false}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 1;
    b.doc["meshes"][0]["primitives"].push_back(second);
    b.setScene({0, b.addNode({{"mesh", 0}, {"translation", {0.0, 0.0, 3.0}}})});
    const Scene s = loadGltf(b.writeDataUri(dir / "instances.gltf")).scene;
    ASSERT_EQ(s.draws.size(), 4u);
    EXPECT_EQ(s.triangleCount(), 4u);
    EXPECT_EQ(s.draws[0].material, 1);
    EXPECT_EQ(s.draws[1].material, 0);
    EXPECT_EQ(s.draws[3].firstIndex, 9u);
    EXPECT_FLOAT_EQ(s.draws[3].wsBounds.min.z, 3.0f);
    EXPECT_FLOAT_EQ(s.wsBounds.max.z, 3.0f);
}

TEST(GltfLoadTest, NonTrianglePrimitivesAreSkippedWithAWarning) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    Json lines = b.doc["meshes"][0]["primitives"][0];
    lines["mode"] = 1;
    b.doc["meshes"][0]["primitives"].push_back(lines);
    const GltfLoadResult r = loadGltf(b.writeDataUri(dir / "lines.gltf"));
    EXPECT_EQ(r.scene.draws.size(), 1u);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("mode 1"), std::string::npos) << r.warnings[0];
}

TEST(GltfLoadTest, ExternalBinWithPercentEncodedName) {
    TempDir dir;
    const Scene s = loadGltf(triangleBuilder().writeExternal(dir / "ext.gltf", "my%20mesh.bin", "my mesh.bin")).scene;
    EXPECT_EQ(s.triangleCount(), 1u);
}

TEST(GltfLoadTest, ExternalBinInSubfolder) {
    TempDir dir;
    fs::create_directory(dir / "data");
    const Scene s = loadGltf(triangleBuilder().writeExternal(dir / "sub.gltf", "data/./tri.bin", "data/tri.bin")).scene;
    EXPECT_EQ(s.triangleCount(), 1u);
}

TEST(GltfLoadTest, UsesTheDefaultScene) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.addNode({{"mesh", 0}, {"translation", {0.0, 7.0, 0.0}}});
    b.doc["scenes"].push_back({{"nodes", {1}}});
    b.doc["scene"] = 1;
    const Scene s = loadGltf(b.writeDataUri(dir / "scenes.gltf")).scene;
    ASSERT_EQ(s.triangleCount(), 1u);
    EXPECT_FLOAT_EQ(s.wsBounds.min.y, 7.0f);
}

TEST(GltfLoadTest, WithoutScenesUsesEveryRootNode) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc.erase("scenes");
    b.doc.erase("scene");
    b.doc["nodes"][0]["children"] = {1};
    b.addNode({{"mesh", 0}, {"translation", {0.0, 2.0, 0.0}}});  // child: drawn once, under node 0
    b.addNode({{"mesh", 0}, {"translation", {0.0, 5.0, 0.0}}});  // a second root
    const Scene s = loadGltf(b.writeDataUri(dir / "roots.gltf")).scene;
    EXPECT_EQ(s.triangleCount(), 3u);
    EXPECT_FLOAT_EQ(s.wsBounds.max.y, 6.0f);
}

TEST(GltfLoadTest, SkinsAndAnimationsAreIgnored) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const int ibm = b.addAccessor(b.addView(identity, sizeof(identity)), kFloat, 1, "MAT4");
    const float times[2] = {0.0f, 1.0f};
    const float moves[6] = {0, 0, 0, 0, 9, 0};
    const int in = b.addAccessor(b.addView(times, sizeof(times)), kFloat, 2, "SCALAR");
    const int out = b.addAccessor(b.addView(moves, sizeof(moves)), kFloat, 2, "VEC3");
    const int joint = b.addNode({{"name", "joint"}});
    b.doc["skins"] = Json::array({{{"joints", Json::array({joint})}, {"inverseBindMatrices", ibm}}});
    b.doc["nodes"][0]["skin"] = 0;
    const Json sampler = {{"input", in}, {"output", out}};
    const Json channel = {{"sampler", 0}, {"target", {{"node", joint}, {"path", "translation"}}}};
    b.doc["animations"] = Json::array({{{"samplers", Json::array({sampler})}, {"channels", Json::array({channel})}}});
    b.setScene({0, joint});
    const GltfLoadResult r = loadGltf(b.writeDataUri(dir / "skinned.gltf"));
    EXPECT_EQ(r.scene.triangleCount(), 1u);
    EXPECT_TRUE(r.warnings.empty());
}

TEST(GltfLoadTest, LoadGltfSceneMatchesLoadGltf) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeGlb(dir / "tri.glb");
    EXPECT_EQ(loadGltfScene(file).vertices.size(), loadGltf(file).scene.vertices.size());
}

}  // namespace
}  // namespace st::test
