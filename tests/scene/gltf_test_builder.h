#pragma once
// Writes tiny glTF files for the loader tests: one buffer, edited freely through `doc` and `bin`
// (hostile cases break them on purpose), saved as .gltf (data: URI or external .bin) or .glb.
#include "renderer/scene/gltf_scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace st::test {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// A fresh directory under the system temp folder, removed with its contents at destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

constexpr int kFloat = 5126;
constexpr int kU8 = 5121;
constexpr int kU16 = 5123;
constexpr int kU32 = 5125;

class GltfBuilder {
public:
    GltfBuilder();

    // Appends bytes (4-aligned) and a buffer view over them; returns the view index.
    int addView(const void* data, std::size_t size, std::size_t byteStride = 0);
    int addAccessor(int view, int componentType, std::size_t count, const std::string& type,
                    std::size_t byteOffset = 0);
    int addVec3(const std::vector<glm::vec3>& values);  // view + FLOAT VEC3 accessor
    int addVec2(const std::vector<glm::vec2>& values);
    int addIndices(const std::vector<std::uint32_t>& indices, int componentType);
    // A mesh with the given primitives, e.g. {{"attributes", {{"POSITION", 0}}}, {"indices", 1}}.
    int addMesh(const Json& primitives);
    int addNode(const Json& node);
    int addMaterial(const Json& material);
    // Sets scenes = [{nodes}] and scene = 0.
    void setScene(const std::vector<int>& nodes);

    // Writers. The buffer goes as a base64 data: URI, an external file, or the GLB BIN chunk.
    // buffers[0].byteLength is bin.size() unless doc sets it.
    fs::path writeDataUri(const fs::path& file) const;
    fs::path writeExternal(const fs::path& file, const std::string& uri, const std::string& binName) const;
    fs::path writeGlb(const fs::path& file) const;

    Json doc;
    std::vector<std::uint8_t> bin;
};

std::string base64(const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgba);
void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes);
void writeText(const fs::path& file, const std::string& text);

// A builder holding one triangle (counter-clockwise seen from +Z) in mesh 0, node 0, scene 0.
// withNormals: NORMAL = +Z; indexed: u16 indices 0 1 2.
GltfBuilder triangleBuilder(bool withNormals = true, bool indexed = true);

// The SceneError message of loading file, or "" when it loads.
std::string loadError(const fs::path& file, const GltfLimits& limits = {});

}  // namespace st::test
