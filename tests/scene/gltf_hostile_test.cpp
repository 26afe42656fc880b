// Broken and hostile files: each is a SceneError naming the file and what is wrong, never a crash
// or a huge allocation.
#include "tests/scene/gltf_test_builder.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <limits>

namespace st::test {
namespace {

// The message names the file and contains every reason fragment.
void expectError(const fs::path& file, std::initializer_list<const char*> reasons, const GltfLimits& limits = {}) {
    const std::string message = loadError(file, limits);
    ASSERT_FALSE(message.empty()) << file << " loaded";
    EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
    for (const char* reason : reasons) EXPECT_NE(message.find(reason), std::string::npos) << message;
}

TEST(GltfHostileTest, MissingFile) {
    TempDir dir;
    expectError(dir / "nothing.gltf", {"not found"});
}

TEST(GltfHostileTest, DirectoryInsteadOfFile) {
    TempDir dir;
    fs::create_directory(dir / "folder.gltf");
    expectError(dir / "folder.gltf", {"not a regular file"});
}

TEST(GltfHostileTest, EmptyFile) {
    TempDir dir;
    writeText(dir / "empty.glb", "");
    expectError(dir / "empty.glb", {"is empty"});
}

TEST(GltfHostileTest, NotJson) {
    TempDir dir;
    writeText(dir / "garbage.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
    expectError(dir / "garbage.gltf", {"not valid JSON"});
}

TEST(GltfHostileTest, NotGltf) {
    TempDir dir;
    writeText(dir / "array.gltf", "[1, 2, 3]");
    expectError(dir / "array.gltf", {"not glTF"});
    writeText(dir / "object.gltf", "{\"nodes\": []}");
    expectError(dir / "object.gltf", {"is not glTF: it has no 'asset' object"});
    writeText(dir / "v1.gltf", "{\"asset\": {\"version\": \"1.0\"}}");
    expectError(dir / "v1.gltf", {"is glTF version '1.0'; only 2.x is read"});
}

TEST(GltfHostileTest, DeeplyNestedJson) {
    TempDir dir;
    const std::string deep = "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + std::string(100000, '[') +
                             std::string(100000, ']') + "}";
    writeText(dir / "deep.gltf", deep);
    expectError(dir / "deep.gltf", {"nested 100001 levels", "maxJsonDepth"});
}

TEST(GltfHostileTest, MissingBin) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeExternal(dir / "nobin.gltf", "nobin.bin", "nobin.bin");
    fs::remove(dir / "nobin.bin");
    expectError(file, {"buffer 0", "'nobin.bin' not found"});
}

TEST(GltfHostileTest, TruncatedBin) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    const fs::path file = b.writeExternal(dir / "short.gltf", "short.bin", "short.bin");
    fs::resize_file(dir / "short.bin", 10);
    expectError(file, {"buffer 0 declares byteLength", "has only 10 bytes (truncated)"});
}

TEST(GltfHostileTest, ByteLengthLargerThanDataUri) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["buffers"][0]["byteLength"] = 1000;
    expectError(b.writeDataUri(dir / "datalen.gltf"), {"byteLength 1000", "data: URI holds"});
}

TEST(GltfHostileTest, ByteLengthLargerThanBinFile) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["buffers"][0]["byteLength"] = 1000;
    expectError(b.writeExternal(dir / "long.gltf", "long.bin", "long.bin"),
                {"buffer 0 declares byteLength 1000", "'long.bin' has only"});
}

TEST(GltfHostileTest, TruncatedGlb) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeGlb(dir / "cut.glb");
    fs::resize_file(file, fs::file_size(file) - 9);
    expectError(file, {"truncated"});
}

TEST(GltfHostileTest, GlbBufferLongerThanBinChunk) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["buffers"][0]["byteLength"] = b.bin.size() + 400;
    expectError(b.writeGlb(dir / "bin.glb"), {"buffer 0 declares byteLength", "GLB BIN chunk holds only"});
}

TEST(GltfHostileTest, GlbChunkTable) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeGlb(dir / "chunks.glb");
    std::vector<std::uint8_t> glb(fs::file_size(file));
    std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(glb.data()), std::streamsize(glb.size()));
    std::vector<std::uint8_t> bad = glb;
    bad[4] = 1;  // version
    writeBytes(file, bad);
    expectError(file, {"GLB version 1"});
    bad = glb;
    bad[12] = 0xff;  // JSON chunk length far past the end
    bad[13] = 0xff;
    writeBytes(file, bad);
    expectError(file, {"GLB JSON chunk declares", "truncated"});
    bad = glb;
    bad.resize(glb.size() - 4);  // BIN chunk cut, header length left as is
    writeBytes(file, bad);
    expectError(file, {"GLB header declares", "truncated"});
    bad = glb;
    bad[8] = 12;  // total length shorter than the header itself (wrapped around once: tests/fuzz/crashes)
    bad[9] = bad[10] = bad[11] = 0;
    writeBytes(file, bad);
    expectError(file, {"GLB header declares 12 bytes, less than its own 20-byte header"});
}

TEST(GltfHostileTest, AccessorPastItsBufferView) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["accessors"][0]["count"] = 4;  // POSITION: 4 * 12 bytes in a 36-byte view
    expectError(b.writeDataUri(dir / "count.gltf"), {"accessor 0 (POSITION of mesh 0 primitive 0)",
                                                     "needs bytes [0, 48) of buffer view 0", "only 36 bytes"});
}

TEST(GltfHostileTest, AccessorStridePastItsBufferView) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["bufferViews"][0]["byteStride"] = 16;  // 2 * 16 + 12 = 44 > 36
    expectError(b.writeDataUri(dir / "stride.gltf"), {"needs bytes [0, 44)"});
}

TEST(GltfHostileTest, AccessorOffsetPastItsBufferView) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["accessors"][1]["byteOffset"] = std::numeric_limits<std::uint32_t>::max();
    expectError(b.writeDataUri(dir / "offset.gltf"), {"accessor 1 (NORMAL", "buffer view 1"});
}

TEST(GltfHostileTest, BufferViewPastItsBuffer) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["bufferViews"][2]["byteLength"] = 4000;
    expectError(b.writeDataUri(dir / "view.gltf"), {"buffer view 2", "overruns buffer 0"});
}

TEST(GltfHostileTest, IndexOutOfRange) {
    TempDir dir;
    GltfBuilder b;
    const int pos = b.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int idx = b.addIndices({0, 1, 3}, kU8);
    b.addMesh(Json::array({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}}));
    b.setScene({b.addNode({{"mesh", 0}})});
    expectError(b.writeDataUri(dir / "index.gltf"), {"index 3", "out of range", "3 vertices"});
}

TEST(GltfHostileTest, NonFinitePositions) {
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        TempDir dir;
        GltfBuilder b = triangleBuilder();
        std::memcpy(&b.bin[4 * 4], &bad, 4);  // vertex 1, y
        expectError(b.writeDataUri(dir / "nan.gltf"), {"POSITION of mesh 0 primitive 0", "non-finite", "vertex 1"});
    }
}

TEST(GltfHostileTest, TransformOverflowsToInfinity) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["nodes"][0]["scale"] = {1e38, 1e38, 1e38};
    b.doc["nodes"][0]["translation"] = {3e38, 0.0, 0.0};
    expectError(b.writeDataUri(dir / "huge.gltf"), {"node 0", "non-finite"});
}

TEST(GltfHostileTest, NoTriangles) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["meshes"][0]["primitives"][0]["mode"] = 0;
    expectError(b.writeDataUri(dir / "points.gltf"), {"contains no triangles", "mode 0"});
    GltfBuilder empty = triangleBuilder();
    empty.doc["nodes"][0].erase("mesh");
    expectError(empty.writeDataUri(dir / "empty.gltf"), {"contains no triangles", "no node"});
}

TEST(GltfHostileTest, AbsurdAccessorCountIsRefusedBeforeAllocating) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["accessors"][0]["count"] = 4'000'000'000ull;
    expectError(b.writeDataUri(dir / "absurd.gltf"), {"4000000000 elements", "maxVertices"});
    b.doc["accessors"][0]["count"] = 3;
    b.doc["accessors"][2]["count"] = 300'000'000;
    expectError(b.writeDataUri(dir / "absurd2.gltf"), {"300000000 elements", "maxIndices"});
}

TEST(GltfHostileTest, SceneLimits) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeDataUri(dir / "limits.gltf");
    GltfLimits few;
    few.maxVertices = 2;
    expectError(file, {"maxVertices"}, few);
    GltfBuilder twice = triangleBuilder();
    twice.setScene({0, 0});
    few.maxVertices = 4;
    expectError(twice.writeDataUri(dir / "twice.gltf"), {"of node 0 takes the scene above 4 vertices (GltfLimits::maxVertices)"}, few);
    few = {};
    few.maxDecodedBytes = 64;
    expectError(file, {"maxDecodedBytes"}, few);
    few = {};
    few.maxFileBytes = 100;
    expectError(file, {"scene file is", "maxFileBytes"}, few);
}

TEST(GltfHostileTest, InstancingExplosionHitsTheNodeLimit) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    // Node k has node k+1 twice as children: 2^40 paths to the mesh.
    for (int k = 1; k <= 40; ++k) b.addNode({{"children", {k + 1, k + 1}}});
    b.doc["nodes"][40]["mesh"] = 0;
    b.doc["nodes"].push_back({{"mesh", 0}});
    b.setScene({1});
    // A small limit: the default (10^6 instances, a triangle each) takes minutes under ASan at -O0.
    GltfLimits limits;
    limits.maxNodeInstances = 10'000;
    expectError(b.writeDataUri(dir / "fanout.gltf"), {"more than 10000 nodes (GltfLimits::maxNodeInstances)"}, limits);
}

TEST(GltfHostileTest, DeepHierarchy) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    for (int k = 1; k <= 300; ++k) b.addNode({{"children", {k + 1}}});
    b.doc["nodes"].push_back({{"mesh", 0}});
    b.setScene({1});
    expectError(b.writeDataUri(dir / "deep.gltf"), {"deeper than 256 levels", "maxNodeDepth"});
}

TEST(GltfHostileTest, NodeCycle) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.addNode({{"children", {2}}});
    b.addNode({{"children", {1}}});
    b.setScene({0, 1});
    expectError(b.writeDataUri(dir / "cycle.gltf"), {"is its own ancestor"});
}

TEST(GltfHostileTest, DanglingReferences) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["nodes"][0]["mesh"] = 7;
    expectError(b.writeDataUri(dir / "mesh.gltf"), {"refers to mesh 7"});
    b = triangleBuilder();
    b.doc["scenes"][0]["nodes"] = {9};
    expectError(b.writeDataUri(dir / "node.gltf"), {"scene 0 refers to node 9"});
    b = triangleBuilder();
    b.doc["meshes"][0]["primitives"][0]["material"] = 3;
    expectError(b.writeDataUri(dir / "material.gltf"), {"refers to material 3"});
    b = triangleBuilder();
    b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 12;
    expectError(b.writeDataUri(dir / "accessor.gltf"), {"NORMAL of mesh 0 primitive 0 refers to accessor 12"});
    b = triangleBuilder();
    b.doc["bufferViews"][0]["buffer"] = 2;
    expectError(b.writeDataUri(dir / "buffer.gltf"), {"buffer view 0 refers to buffer 2"});
}

TEST(GltfHostileTest, WrongAccessorTypes) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["accessors"][0]["type"] = "VEC2";
    expectError(b.writeDataUri(dir / "type.gltf"), {"has type VEC2, expected VEC3"});
    b = triangleBuilder();
    b.doc["accessors"][2]["componentType"] = 5122;  // SHORT
    expectError(b.writeDataUri(dir / "indextype.gltf"), {"indices must be unsigned"});
    b = triangleBuilder();
    b.doc["accessors"][1]["count"] = 2;
    expectError(b.writeDataUri(dir / "normalcount.gltf"), {"NORMAL of mesh 0 primitive 0 has 2 elements"});
}

TEST(GltfHostileTest, BadNodeTransforms) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["nodes"][0]["matrix"] = {1, 0, 0};
    expectError(b.writeDataUri(dir / "matrix.gltf"), {"'matrix' has 3 numbers, not 16"});
    b = triangleBuilder();
    b.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
    expectError(b.writeDataUri(dir / "rotation.gltf"), {"zero or non-finite rotation"});
}

TEST(GltfHostileTest, SparseAccessorsAreSkipped) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", 2}, {"componentType", kU16}}},
                                       {"values", {{"bufferView", 0}}}};
    expectError(b.writeDataUri(dir / "sparse.gltf"), {"contains no triangles", "is sparse, which is not supported"});
}

TEST(GltfHostileTest, CompressedGeometryIsRefused) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectError(b.writeDataUri(dir / "draco.gltf"), {"KHR_draco_mesh_compression", "not supported"});
}

}  // namespace
}  // namespace st::test
