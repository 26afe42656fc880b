#pragma once
// Internals of the glTF loader (gltf_*.cpp), shared between its files only.
// tinygltf comes from Debian's compiled libtinygltf.so (built with stb_image): this project
// never defines TINYGLTF_IMPLEMENTATION. Everything tinygltf does not check is checked here.
#include "renderer/scene/gltf_scene.h"

#include <tiny_gltf.h>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace st::gltf {

// State of one load: limits, budgets, warnings, and the file named in every message.
struct LoadContext {
    std::filesystem::path file;      // as the caller gave it
    std::filesystem::path sceneDir;  // canonical folder of the file: URIs must stay inside
    GltfLimits limits;
    std::vector<std::string> warnings;
    std::set<std::string> warned;         // each warning once
    std::uint64_t fileBytesRead = 0;      // against limits.maxTotalFileBytes
    std::uint64_t decodedBytes = 0;       // against limits.maxDecodedBytes
    std::string fsRefusal;                // first path refused inside a tinygltf callback
    bool usesDefaultMaterial = false;     // some primitive has no material (see convertMaterials)
    std::map<int, std::string> unreadableImages;  // image index -> why it cannot be used

    [[noreturn]] void fail(const std::string& what) const;  // throws SceneError "<file>: what"
    void warn(const std::string& what);
    // Adds bytes to the decoded budget, or fails naming what needed them.
    void chargeDecoded(std::uint64_t bytes, const std::string& what);
};

// ---- files and URIs (gltf_files.cpp)
// Reads a whole file, refusing non-regular files and anything above the limits. `what` names the
// file's role in messages ("buffer 0 file 'a.bin'").
std::vector<std::uint8_t> readFileChecked(LoadContext& ctx, const std::filesystem::path& path,
                                          const std::string& what);
// Percent-decoding exactly as tinygltf does before it opens a file ('+' becomes a space too).
std::string decodeUri(const std::string& uri);
bool isDataUri(std::string_view uri);
// Why an (undecoded) URI may not be opened, or nullopt when it is a relative path inside.
std::optional<std::string> uriRefusal(const LoadContext& ctx, const std::string& uri);
// Whether an absolute path, symlinks resolved, lies inside ctx.sceneDir.
bool insideSceneDir(const LoadContext& ctx, const std::filesystem::path& path);
// Deepest nesting of [ and { outside strings.
int jsonNestingDepth(std::string_view json);

struct GlbChunks {
    std::string_view json;
    std::size_t glbLength = 0;     // the header's total length (bytes handed to tinygltf)
    std::size_t binSize = 0;       // 0 when there is no BIN chunk
    bool hasBin = false;
};
// Validates the GLB header and chunk table (stricter than tinygltf 2.7.0, which can read 8 bytes
// past a truncated BIN chunk).
GlbChunks splitGlb(const LoadContext& ctx, const std::vector<std::uint8_t>& bytes);

// ---- checks on the raw JSON before tinygltf reads any buffer or image (gltf_prepass.cpp)
// Buffers (URI rule, existence, byteLength vs file / data: URI / BIN chunk), buffer views inside
// their buffers, image URIs. tinygltf 2.7.0 trusts buffer views when it decodes GLB images, and
// fails the whole load on a data: image it cannot decode: such images are replaced by a stub
// (noted in ctx.unreadableImages) and the edited JSON is returned; nullopt when nothing changed.
std::optional<std::string> prevalidateJson(LoadContext& ctx, std::string_view json,
                                           const GlbChunks* glb);

// ---- tinygltf (gltf_parse.cpp)
tinygltf::Model parseModel(LoadContext& ctx);

// ---- accessors (gltf_accessor.cpp)
// A validated accessor: every element lies inside its buffer (data is never null).
struct AccessorView {
    const std::uint8_t* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};
// role names the use in messages ("POSITION of mesh 0 primitive 1"); expectedType is a
// TINYGLTF_TYPE_* (SCALAR: indices, limited by maxIndices; else maxVertices). Fails on any
// inconsistency. Returns nullopt, with a warning, for what is valid but not read: sparse
// accessors and accessors without a buffer view (all zeros).
std::optional<AccessorView> viewAccessor(LoadContext& ctx, const tinygltf::Model& model,
                                         int accessor, int expectedType, const std::string& role);
std::vector<glm::vec3> readVec3(const AccessorView& view);
std::vector<glm::vec2> readVec2(const AccessorView& view);
// Unsigned byte/short/int only (fails otherwise).
std::vector<std::uint32_t> readIndices(LoadContext& ctx, const AccessorView& view,
                                       const std::string& role);

// ---- images and materials (gltf_images.cpp, gltf_materials.cpp)
// tinygltf image callback: keeps the encoded bytes (as_is) so only used images get decoded.
bool keepEncodedImage(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                      int reqWidth, int reqHeight, const unsigned char* bytes, int size,
                      void* ctx);
// RGBA8, or nullopt with a warning (unreadable, undecodable or above the limits).
std::optional<Image> decodeImage(LoadContext& ctx, const tinygltf::Image& image, int index);
// One Material per glTF material, textures decoded into scene.images, then the default Material
// when ctx.usesDefaultMaterial. Runs after the geometry, so textures get what the budget leaves.
void convertMaterials(LoadContext& ctx, const tinygltf::Model& model, Scene& scene);

// ---- geometry (gltf_mesh.cpp, gltf_nodes.cpp)
struct MeshInstance {
    glm::mat4 wsFromLocal{1.0f};
    glm::mat3 wsNormalFromLocal{1.0f};  // inverse transpose of the upper 3x3
    bool flipWinding = false;           // negative determinant
    bool singular = false;              // (near) zero determinant: flat normals from the result
    std::string nodeLabel;              // "node 3 ('Trunk')"
};
struct GeometryStats {
    std::size_t primitivesSkipped = 0;
    std::size_t meshInstances = 0;
};
// Appends one primitive instance as one DrawItem (material indices as convertMaterials makes them).
void appendPrimitive(LoadContext& ctx, const tinygltf::Model& model, int mesh, int primitive,
                     const MeshInstance& instance, Scene& scene, GeometryStats& stats);
// Walks the chosen scene's node trees and appends every mesh instance.
void appendSceneNodes(LoadContext& ctx, const tinygltf::Model& model, Scene& scene,
                      GeometryStats& stats);

}  // namespace st::gltf
