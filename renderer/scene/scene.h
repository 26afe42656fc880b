#pragma once
// CPU scene: world-space triangles ready to upload and to ray-cast. No GL.
// Node transforms are applied at load time (winding flipped where the determinant is negative),
// so the renderer, the culling and the ground truth all see exactly the same triangles.
#include "renderer/csm/geometry.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace st {

struct Vertex {
    glm::vec3 position{0.0f};  // ws, metres
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4
};

struct Material {
    glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};
    int baseColorTexture = -1;  // index into Scene::images, -1 = none
    bool alphaMask = false;     // glTF alphaMode MASK: alpha-tested in every pass
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

// One draw call: a range of Scene::indices with its material and world bounds (for culling).
struct DrawItem {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    int material = 0;
    csm::Aabb wsBounds;
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise front faces
    std::vector<DrawItem> draws;
    std::vector<Material> materials;
    std::vector<Image> images;
    csm::Aabb wsBounds;  // of all triangles
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Loading failed: the message names the file and what is wrong.
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What a preset adds to the scene it loads (Settings::ground).
struct SceneOptions {
    bool ground = false;  // a square quad at the lowest point, 4x the larger horizontal extent, centred
    bool operator==(const SceneOptions&) const = default;
};

// "builtin:NAME" (builtinSceneNames(): yard, box-over-plane, empty and the small scenes of
// presets/scenarios/), or a .gltf/.glb path (relative paths are resolved against baseDir, the
// preset's folder). Throws SceneError.
Scene loadScene(const std::string& spec, const std::filesystem::path& baseDir, const SceneOptions& options = {});

// Equal for two (spec, baseDir, options) that load the same scene: a key for caches.
std::string sceneKey(const std::string& spec, const std::filesystem::path& baseDir, const SceneOptions& options = {});

// Appends the ground of SceneOptions under s's current bounds (recomputed after).
void addGroundUnder(Scene& s);

// Names accepted after "builtin:".
std::vector<std::string> builtinSceneNames();
Scene makeBuiltinScene(const std::string& name);  // throws SceneError for an unknown name

// Appends an axis-aligned box / a horizontal quad as one DrawItem with flat normals.
void addBox(Scene& s, glm::vec3 wsMin, glm::vec3 wsMax, int material);
void addGroundQuad(Scene& s, float halfSize, float y, int material);
void finalizeBounds(Scene& s);  // recompute every DrawItem's bounds and the scene bounds

}  // namespace st
