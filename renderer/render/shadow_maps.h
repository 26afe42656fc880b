#pragma once
// The cascades' depth maps as csm::StorageLayout describes them (cascades.storage): one D32F
// array with a layer per cascade, one atlas with a tile per cascade, or one texture per cascade
// (each a one-layer D32F array, so every storage samples and reads back alike), with the
// framebuffer the shadow pass draws through and the compare samplers. Reallocated only when the
// layout's textures change.
#include "renderer/csm/storage_layout.h"
#include "renderer/gpu/gl.h"
#include "renderer/gpu/pass_state.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace st {

class ShadowMaps {
public:
    void ensure(const csm::StorageLayout& layout);  // (re)allocates when the textures differ
    // Starts cascade i's depth pass: its texture and layer attached to framebuffer(), `state`
    // applied with the viewport (and scissor) of its tile, the tile cleared to depth 1. The atlas's
    // padding is cleared once at allocation and never drawn into, so it stays lit.
    void beginCascade(int cascade, gpu::PassState state) const;
    GLuint framebuffer() const { return fbo_.id(); }
    // Array and atlas: the one texture on both shadow bindings (nearest and linear compare) and,
    // raw, on ST_BINDING_SHADOW_RAW (PCSS); textures: texture i on ST_BINDING_CASCADE_MAPS + i
    // with linear compare.
    void bindForSampling() const;
    void unbindSamplers() const;
    const csm::StorageLayout& layout() const { return layout_; }
    int cascades() const { return static_cast<int>(layout_.tiles.size()); }
    const csm::MapTile& tile(int cascade) const { return layout_.tiles[static_cast<std::size_t>(cascade)]; }
    // The texture holding cascade i's map (GL_TEXTURE_2D_ARRAY, D32F).
    GLuint texture(int cascade = 0) const;
    GLuint textureAt(int index) const { return textures_[static_cast<std::size_t>(index)].id(); }
    int textureCount() const { return static_cast<int>(textures_.size()); }
    glm::ivec4 viewport(int cascade) const;  // x, y, width, height of its tile, texels
    std::size_t bytes() const { return csm::storageBytes(layout_); }

private:
    std::vector<gpu::Texture> textures_;
    gpu::Framebuffer fbo_;
    gpu::Sampler nearest_;
    gpu::Sampler linear_;
    csm::StorageLayout layout_;
    gpu::Sampler raw_;
};

// Reads cascade i's tile back as depth values, row by row from the bottom (size x size floats).
std::vector<float> readCascadeDepth(const ShadowMaps& maps, int cascade);

}  // namespace st
