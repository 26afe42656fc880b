// URIs: the folder rule, data: and percent-encoded URIs; images that cannot be used fall back to
// the base colour factor with a warning.
#include "tests/scene/gltf_test_builder.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace st::test {
namespace {

void expectRefused(const std::string& uri, std::initializer_list<const char*> reasons) {
    TempDir dir;
    const fs::path file = triangleBuilder().writeExternal(dir / "uri.gltf", uri, "unused.bin");
    const std::string message = loadError(file);
    ASSERT_FALSE(message.empty()) << uri << " was read";
    EXPECT_NE(message.find("uri.gltf"), std::string::npos) << message;
    for (const char* reason : reasons) EXPECT_NE(message.find(reason), std::string::npos) << message;
}

TEST(GltfUriTest, EscapingAndAbsoluteUrisAreRefused) {
    expectRefused("../../etc/passwd", {"buffer 0 URI '../../etc/passwd' escapes the scene folder"});
    expectRefused("sub/../../secret.bin", {"escapes the scene folder"});
    expectRefused("%2e%2e/%2E%2E/etc/passwd", {"escapes the scene folder"});
    expectRefused("/etc/passwd", {"is an absolute path"});
    expectRefused("%2Fetc%2Fpasswd", {"is an absolute path"});
    expectRefused("file:///etc/passwd", {"is an absolute file: URI"});
    expectRefused("http://example.com/a.bin", {"uses the scheme 'http:'; only files inside"});
    expectRefused("C:/Windows/win.ini", {"drive letter"});
}

TEST(GltfUriTest, SymlinkOutOfTheFolderIsRefused) {
    TempDir outside;
    TempDir dir;
    const GltfBuilder b = triangleBuilder();
    writeBytes(outside / "real.bin", b.bin);
    fs::create_symlink(outside / "real.bin", dir / "link.bin");
    const fs::path file = b.writeExternal(dir / "link.gltf", "link.bin", "unused.bin");
    const std::string message = loadError(file);
    EXPECT_NE(message.find("resolves outside the scene folder"), std::string::npos) << message;
}

TEST(GltfUriTest, GltfBufferMediaTypeWorks) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["buffers"][0]["byteLength"] = b.bin.size();
    b.doc["buffers"][0]["uri"] = "data:application/gltf-buffer;base64," + base64(b.bin);
    writeText(dir / "gltfbuffer.gltf", b.doc.dump());
    EXPECT_EQ(loadGltf(dir / "gltfbuffer.gltf").scene.triangleCount(), 1u);
}

TEST(GltfUriTest, DataUriBufferInsideGlbWorks) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    b.doc["buffers"][0]["byteLength"] = b.bin.size();
    b.doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(b.bin);
    EXPECT_EQ(loadGltf(b.writeGlb(dir / "datauri.glb")).scene.triangleCount(), 1u);
}

// Gives triangle mesh 0 a textured material whose image is `image` (a glTF image object).
void texture(GltfBuilder& b, const Json& image) {
    b.doc["images"] = Json::array({image});
    b.doc["textures"] = Json::array({{{"source", 0}}});
    b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {1, 0.5, 0, 1}}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addVec2({{0, 0}, {1, 0}, {0, 1}});
}

// Loads and expects the texture to have fallen back to the factor with a warning holding reason.
void expectImageFallback(const fs::path& file, const char* reason, const GltfLimits& limits = {}) {
    const GltfLoadResult r = loadGltf(file, limits);
    EXPECT_TRUE(r.scene.images.empty());
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_EQ(r.scene.materials[0].baseColorTexture, -1);
    EXPECT_FLOAT_EQ(r.scene.materials[0].baseColor.y, 0.5f);
    const bool found = std::any_of(r.warnings.begin(), r.warnings.end(),
                                   [&](const std::string& w) { return w.find(reason) != std::string::npos; });
    EXPECT_TRUE(found) << "no warning with '" << reason << "' among " << ::testing::PrintToString(r.warnings);
    for (const std::string& w : r.warnings) EXPECT_NE(w.find("base colour factor"), std::string::npos) << w;
}

const std::vector<std::uint8_t> kPixel = {200, 100, 50, 255};

TEST(GltfUriTest, ExternalImageWithPercentEncodedName) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "my%20tex.png"}});
    writeBytes(dir / "my tex.png", encodePng(1, 1, kPixel));
    const Scene s = loadGltf(b.writeDataUri(dir / "tex.gltf")).scene;
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba, kPixel);
}

TEST(GltfUriTest, GlbImageInBufferView) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    const std::vector<std::uint8_t> png = encodePng(1, 1, kPixel);
    texture(b, {{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}});
    const Scene s = loadGltf(b.writeGlb(dir / "tex.glb")).scene;
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba, kPixel);
}

TEST(GltfUriTest, EscapingImageUriIsRefused) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "../../etc/passwd"}});
    const std::string message = loadError(b.writeDataUri(dir / "img.gltf"));
    EXPECT_NE(message.find("img.gltf"), std::string::npos) << message;
    EXPECT_NE(message.find("image 0 URI '../../etc/passwd' escapes the scene folder"), std::string::npos) << message;
}

TEST(GltfUriTest, MissingImageFallsBack) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "missing.png"}});
    expectImageFallback(b.writeDataUri(dir / "missing.gltf"), "image 0 ('missing.png') could not be read");
}

TEST(GltfUriTest, UndecodableImageFallsBack) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "data:image/png;base64," + base64({1, 2, 3, 4, 5, 6, 7, 8, 9})}});
    expectImageFallback(b.writeDataUri(dir / "garbage.gltf"), "cannot be decoded");
}

// SOI, then a Huffman table whose 16 code counts (0x11 each) sum to 272: more than the 256 codes a
// table holds. Debian's stb_image writes past its arrays on this (tests/fuzz/crashes/gltf).
TEST(GltfUriTest, JpegWithOversizedHuffmanTableFallsBack) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "data:image/jpeg;base64,/9j/xAATABERERERERERERERERERERE="}});
    expectImageFallback(b.writeDataUri(dir / "dht.gltf"), "corrupt JPEG (a Huffman table with more than 256 codes)");
}

TEST(GltfUriTest, UnsupportedDataUriImageFallsBack) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "data:image/webp;base64,UklGRg=="}});
    expectImageFallback(b.writeDataUri(dir / "webp.gltf"), "not base64 PNG or JPEG");
    expectImageFallback(b.writeGlb(dir / "webp.glb"), "not base64 PNG or JPEG");
}

TEST(GltfUriTest, OversizedImageIsNotDecoded) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    std::vector<std::uint8_t> png = encodePng(1, 1, kPixel);
    // IHDR width and height (big-endian) at bytes 16..23: 20000 x 20000. stb does not check CRCs.
    for (int at : {16, 20}) {
        png[static_cast<std::size_t>(at + 2)] = 20000 >> 8;
        png[static_cast<std::size_t>(at + 3)] = 20000 & 0xff;
    }
    texture(b, {{"uri", "data:image/png;base64," + base64(png)}});
    expectImageFallback(b.writeDataUri(dir / "huge.gltf"), "is 20000x20000, outside 1..16384");
}

TEST(GltfUriTest, ImageAboveTheDecodedBudgetIsNotDecoded) {
    TempDir dir;
    GltfBuilder b = triangleBuilder();
    texture(b, {{"uri", "data:image/png;base64," + base64(encodePng(64, 64, std::vector<std::uint8_t>(64 * 64 * 4, 9)))}});
    GltfLimits limits;
    limits.maxDecodedBytes = 10'000;
    expectImageFallback(b.writeDataUri(dir / "budget.gltf"), "maxDecodedBytes", limits);
}

}  // namespace
}  // namespace st::test
