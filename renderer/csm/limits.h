#pragma once
// Sizes the cascade math, the settings, the UI and the renderer agree on. Header-only, so the
// settings library (which does not link st_csm) can use it too.
#include "shaders/codes.h"

#include <algorithm>
#include <cstddef>

namespace st::csm {

// The most cascades a preset may ask for; the shaders' arrays hold this many.
inline constexpr int kMaxCascades = ST_MAX_CASCADES;

// Bytes per shadow-map texel: the depth array is GL_DEPTH_COMPONENT32F (renderer/render/shadow_maps).
inline constexpr std::size_t kShadowTexelBytes = 4;

// Memory of `layers` square shadow maps of `size` texels a side; negative inputs count as 0.
inline constexpr std::size_t shadowMapBytes(int layers, int size) {
    const auto side = static_cast<std::size_t>(std::max(size, 0));
    return static_cast<std::size_t>(std::max(layers, 0)) * side * side * kShadowTexelBytes;
}

}  // namespace st::csm
