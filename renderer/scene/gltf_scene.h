#pragma once
// glTF 2.0 (.gltf with external or data: buffers and images, .glb) to the CPU Scene.
//
// What is read: the default scene (else scene 0, else every root node); node matrices or TRS;
// TRIANGLES primitives (other modes are skipped with a warning) with u8/u16/u32 or no indices;
// POSITION, NORMAL (generated flat when missing), TEXCOORD_0; base colour factor and texture,
// alphaMode MASK + alphaCutoff, doubleSided. Skins, morph targets and animations are ignored (bind
// pose). Node transforms are applied: positions to world space, normals by the inverse transpose,
// and the winding is swapped under a negative determinant so front faces stay counter-clockwise.
//
// Hostile input never crashes or allocates without bound: every failure is a SceneError whose
// message starts with the file and says what is wrong. URIs must stay inside the scene's folder
// (no "..", no absolute path, no scheme other than data:); percent-escapes are decoded first.
// Images that cannot be read, decoded, or are above the limits only warn: the material falls
// back to its base colour factor.
#include "renderer/scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace st {

// Every number is checked before the memory it implies is allocated.
struct GltfLimits {
    std::uint64_t maxFileBytes = 1ull << 30;         // any one file read: .gltf/.glb/.bin/image
    std::uint64_t maxTotalFileBytes = 2ull << 30;    // all files read for one scene
    std::uint64_t maxJsonBytes = 256ull << 20;       // the JSON text (.gltf or GLB JSON chunk)
    int maxJsonDepth = 64;                           // nesting of [ and {: guards recursion
    std::uint64_t maxVertices = 50'000'000;          // output Scene::vertices, and per accessor
    std::uint64_t maxIndices = 100'000'000;          // output Scene::indices, and per accessor
    std::uint64_t maxDecodedBytes = 3ull << 30;      // output vertices + indices + RGBA8 images
    int maxImageDimension = 16384;                   // width and height, read from the header
    std::uint64_t maxNodeInstances = 1'000'000;      // node visits (instancing fans out)
    int maxNodeDepth = 256;                          // node hierarchy depth
};

struct GltfLoadResult {
    Scene scene;                        // bounds computed (finalizeBounds not needed)
    std::vector<std::string> warnings;  // one sentence each, without the file name
};

// Throws SceneError ("<file>: <what is wrong>").
GltfLoadResult loadGltf(const std::filesystem::path& file, const GltfLimits& limits = {});

// loadGltf with the default limits; prints each warning to stderr as
// "shadowtune: <file>: warning: <text>".
Scene loadGltfScene(const std::filesystem::path& file);

}  // namespace st
