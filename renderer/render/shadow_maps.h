#pragma once
// The cascades' depth maps as csm::StorageLayout describes them (cascades.storage): one D32F
// array with a layer per cascade, one atlas with a tile per cascade, or one texture per cascade
// (each a one-layer D32F array, so every storage samples and reads back alike), with the
// framebuffer the shadow pass draws through and the compare samplers. Reallocated only when the
// layout's textures change.
// Two sets can be held: the full-quality one and the editor's interactive preview's smaller one
// (MapSet::Preview). A preview frame draws into its own set, so the full-size maps survive it and
// the full frame after a move does not pay their allocation and clear again (issue 39 #1: 145 ms
// for 4 x 4096², a first full frame of 1.06-1.17 s against 0.67 s). Headless runs use one set.
#include "renderer/csm/storage_layout.h"
#include "renderer/gpu/gl.h"
#include "renderer/gpu/pass_state.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace st {

enum class MapSet { Full, Preview };

class ShadowMaps {
public:
    // Makes `layout` the maps drawn and sampled: a held set with these textures, else `set`'s
    // (re)allocated. A full frame matching the preview set takes it over and frees the old full
    // set, so the second set never holds more than the preview's maps.
    void ensure(const csm::StorageLayout& layout, MapSet set = MapSet::Full);
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
    // The maps of the last ensure() (the ones drawn and sampled).
    const csm::StorageLayout& layout() const { return active().layout; }
    int cascades() const { return static_cast<int>(layout().tiles.size()); }
    const csm::MapTile& tile(int cascade) const { return layout().tiles[static_cast<std::size_t>(cascade)]; }
    // The texture holding cascade i's map (GL_TEXTURE_2D_ARRAY, D32F).
    GLuint texture(int cascade = 0) const;
    GLuint textureAt(int index) const { return active().textures[static_cast<std::size_t>(index)].id(); }
    int textureCount() const { return static_cast<int>(active().textures.size()); }
    glm::ivec4 viewport(int cascade) const;  // x, y, width, height of its tile, texels
    std::size_t bytes() const { return csm::storageBytes(layout()); }
    // A set as held, drawn or not (no textures: none held), for the memory breakdown.
    const csm::StorageLayout& held(MapSet set) const { return sets_[index(set)].layout; }
    int allocations() const { return allocations_; }  // sets allocated so far

private:
    struct Allocation {
        std::vector<gpu::Texture> textures;
        csm::StorageLayout layout;  // no textures while none are held
        bool holds(const csm::StorageLayout& l) const;
    };
    static std::size_t index(MapSet set) { return set == MapSet::Full ? 0 : 1; }
    const Allocation& active() const { return sets_[active_]; }
    void allocate(Allocation& a, const csm::StorageLayout& layout);
    Allocation sets_[2];      // MapSet::Full, MapSet::Preview
    std::size_t active_ = 0;  // the set of the last ensure()
    int allocations_ = 0;
    gpu::Framebuffer fbo_;
    gpu::Sampler nearest_;
    gpu::Sampler linear_;
    gpu::Sampler raw_;
};

// Reads cascade i's tile back as depth values, row by row from the bottom (size x size floats).
std::vector<float> readCascadeDepth(const ShadowMaps& maps, int cascade);

}  // namespace st
