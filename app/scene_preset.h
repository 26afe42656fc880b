#pragma once
// A preset for a glTF scene of the user's own (`shadowtune init`, and `render`/`editor` given a
// .gltf or .glb): the camera frames the scene's bounds, the sun is the default one, a ground goes
// under a scene with no floor of its own, and the cascades span the scene as seen, not the default
// preset's 400 m. Nothing of another scene (its notes, splits, problems) carries over.
#include "renderer/settings/settings.h"

#include <filesystem>

namespace st::app {

// True for a path ending in .gltf or .glb (any case).
bool isGltfPath(const std::filesystem::path& path);

// The preset for `gltf`, its scene path written relative to `presetDir` (where the preset will be
// saved), or absolute when presetDir is empty (a document not saved yet). Throws SceneError when the file does not load, std::runtime_error when it holds no triangles.
Settings presetForScene(const std::filesystem::path& gltf, const std::filesystem::path& presetDir);

}  // namespace st::app
