#include "tests/scene/gltf_test_builder.h"

#include <cstring>
#include <fstream>
#include <random>
#include <stdexcept>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace st::test {

TempDir::TempDir() {
    std::random_device random;
    for (int attempt = 0; attempt < 100; ++attempt) {
        path_ = fs::temp_directory_path() / ("st_gltf_test_" + std::to_string(random()));
        if (fs::create_directory(path_)) return;
    }
    throw std::runtime_error("cannot create a temporary directory");
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

GltfBuilder::GltfBuilder() {
    doc = {{"asset", {{"version", "2.0"}}}, {"buffers", Json::array({Json::object()})}, {"bufferViews", Json::array()},
           {"accessors", Json::array()}, {"meshes", Json::array()}, {"nodes", Json::array()}};
}

int GltfBuilder::addView(const void* data, std::size_t size, std::size_t byteStride) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    Json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
    if (byteStride != 0) view["byteStride"] = byteStride;
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    bin.insert(bin.end(), bytes, bytes + size);
    doc["bufferViews"].push_back(view);
    return static_cast<int>(doc["bufferViews"].size()) - 1;
}

int GltfBuilder::addAccessor(int view, int componentType, std::size_t count, const std::string& type,
                             std::size_t byteOffset) {
    Json accessor = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (byteOffset != 0) accessor["byteOffset"] = byteOffset;
    doc["accessors"].push_back(accessor);
    return static_cast<int>(doc["accessors"].size()) - 1;
}

int GltfBuilder::addVec3(const std::vector<glm::vec3>& values) {
    const int view = addView(values.data(), values.size() * sizeof(glm::vec3));
    return addAccessor(view, kFloat, values.size(), "VEC3");
}

int GltfBuilder::addVec2(const std::vector<glm::vec2>& values) {
    const int view = addView(values.data(), values.size() * sizeof(glm::vec2));
    return addAccessor(view, kFloat, values.size(), "VEC2");
}

int GltfBuilder::addIndices(const std::vector<std::uint32_t>& indices, int componentType) {
    const std::size_t size = componentType == kU8 ? 1 : componentType == kU16 ? 2 : 4;
    std::vector<std::uint8_t> bytes(indices.size() * size);
    for (std::size_t i = 0; i < indices.size(); ++i) std::memcpy(&bytes[i * size], &indices[i], size);  // little-endian
    const int view = addView(bytes.data(), bytes.size());
    return addAccessor(view, componentType, indices.size(), "SCALAR");
}

int GltfBuilder::addMesh(const Json& primitives) {
    doc["meshes"].push_back({{"primitives", primitives}});
    return static_cast<int>(doc["meshes"].size()) - 1;
}

int GltfBuilder::addNode(const Json& node) {
    doc["nodes"].push_back(node);
    return static_cast<int>(doc["nodes"].size()) - 1;
}

int GltfBuilder::addMaterial(const Json& material) {
    doc["materials"].push_back(material);
    return static_cast<int>(doc["materials"].size()) - 1;
}

void GltfBuilder::setScene(const std::vector<int>& nodes) {
    doc["scenes"] = Json::array({{{"nodes", nodes}}});
    doc["scene"] = 0;
}

fs::path GltfBuilder::writeDataUri(const fs::path& file) const {
    Json out = doc;
    if (!out["buffers"][0].contains("byteLength")) out["buffers"][0]["byteLength"] = bin.size();
    out["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
    writeText(file, out.dump());
    return file;
}

fs::path GltfBuilder::writeExternal(const fs::path& file, const std::string& uri, const std::string& binName) const {
    Json out = doc;
    if (!out["buffers"][0].contains("byteLength")) out["buffers"][0]["byteLength"] = bin.size();
    out["buffers"][0]["uri"] = uri;
    writeText(file, out.dump());
    writeBytes(file.parent_path() / binName, bin);
    return file;
}

namespace {

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    out.insert(out.end(), p, p + 4);
}

}  // namespace

fs::path GltfBuilder::writeGlb(const fs::path& file) const {
    Json out = doc;
    if (!out["buffers"][0].contains("byteLength")) out["buffers"][0]["byteLength"] = bin.size();
    std::string json = out.dump();
    json.resize((json.size() + 3) / 4 * 4, ' ');
    std::vector<std::uint8_t> chunkBin = bin;
    chunkBin.resize((chunkBin.size() + 3) / 4 * 4, 0);
    std::vector<std::uint8_t> glb = {'g', 'l', 'T', 'F'};
    appendU32(glb, 2);
    appendU32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + chunkBin.size()));
    appendU32(glb, static_cast<std::uint32_t>(json.size()));
    appendU32(glb, 0x4E4F534Au);
    glb.insert(glb.end(), json.begin(), json.end());
    appendU32(glb, static_cast<std::uint32_t>(chunkBin.size()));
    appendU32(glb, 0x004E4942u);
    glb.insert(glb.end(), chunkBin.begin(), chunkBin.end());
    writeBytes(file, glb);
    return file;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t a = bytes[i];
        const std::uint32_t b = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const std::uint32_t c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t triple = (a << 16) | (b << 8) | c;
        out += alphabet[(triple >> 18) & 63];
        out += alphabet[(triple >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[triple & 63] : '=';
    }
    return out;
}

std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> png;
    auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4)) {
        throw std::runtime_error("PNG encoding failed");
    }
    return png;
}

void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

void writeText(const fs::path& file, const std::string& text) {
    writeBytes(file, std::vector<std::uint8_t>(text.begin(), text.end()));
}

GltfBuilder triangleBuilder(bool withNormals, bool indexed) {
    GltfBuilder b;
    Json attributes = {{"POSITION", b.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}};
    if (withNormals) attributes["NORMAL"] = b.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    Json primitive = {{"attributes", attributes}};
    if (indexed) primitive["indices"] = b.addIndices({0, 1, 2}, kU16);
    b.addMesh(Json::array({primitive}));
    b.setScene({b.addNode({{"mesh", 0}})});
    return b;
}

std::string loadError(const fs::path& file, const GltfLimits& limits) {
    try {
        loadGltf(file, limits);
    } catch (const SceneError& e) {
        return e.what();
    }
    return {};
}

}  // namespace st::test
