#pragma once
// A Scene's triangles as a binary glTF (.glb), for the engines engine-check runs (engines/README.md):
// built-in scenes and the ground quad exist only inside shadowtune, so the engine loads them from
// this file with its own glTF loader. World-space positions and normals, one primitive per draw,
// the draws' materials (base colour factor, double-sidedness, alpha mask); no textures.
#include "renderer/scene/scene.h"

#include <cstddef>
#include <string>

namespace st {

// The draws [firstDraw, end) of `scene` as the bytes of a .glb (glTF 2.0 binary container).
std::string glbOfDraws(const Scene& scene, std::size_t firstDraw = 0);

}  // namespace st
