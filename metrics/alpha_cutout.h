#pragma once
// The alpha test of the GL passes, on the CPU, so ray-cast ground truth cuts foliage cards
// exactly where the renderer does: glTF alphaMode MASK discards where
// baseColor.a * texture.a < alphaCutoff (shaders/shadow_depth.frag, main.frag).
#include "renderer/scene/scene.h"

#include <glm/vec2.hpp>

namespace st::metrics {

// Bilinear alpha of `img` at `uv` from the full-resolution level, with GL_REPEAT wrapping and
// texel centres at (i + 0.5) / size like the GL texture (rows upload top first, so uv (0,0) is
// the first pixel of the image). The GL shadow pass reads a mip level chosen by the shadow
// texel's footprint; level 0 is the exact cut-out that both approximate.
float sampleAlpha(const Image& img, glm::vec2 uv);

// baseColor.a times the base-colour texture's alpha (if it has a valid one).
float materialAlpha(const Scene& scene, const Material& m, glm::vec2 uv);

// True where an alpha-masked material is cut away (lets light through).
bool cutOut(const Scene& scene, const Material& m, glm::vec2 uv);

}  // namespace st::metrics
