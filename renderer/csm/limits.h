#pragma once
// The bytes of shadow maps, which the storage layout, the UI and the renderer agree on.
// (The most cascades a preset may ask for, kMaxCascades, is a limit of the settings: settings.h.)
#include <algorithm>
#include <cstddef>

namespace st::csm {

// Bytes per shadow-map texel: the depth array is GL_DEPTH_COMPONENT32F (renderer/render/shadow_maps).
inline constexpr std::size_t kShadowTexelBytes = 4;

// Memory of `layers` square shadow maps of `size` texels a side; negative inputs count as 0.
inline constexpr std::size_t shadowMapBytes(int layers, int size) {
    const auto side = static_cast<std::size_t>(std::max(size, 0));
    return static_cast<std::size_t>(std::max(layers, 0)) * side * side * kShadowTexelBytes;
}

}  // namespace st::csm
