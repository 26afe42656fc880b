#include "renderer/render/shadow_maps.h"

#include "shaders/interface.h"

#include <string>
#include <utility>

namespace st {
namespace {
gpu::Sampler compareSampler(GLenum filter) {
    gpu::Sampler s = gpu::createSampler();
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, filter);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, filter);
    // Outside the map counts as lit: border depth 1 compares as "not occluded".
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glSamplerParameterfv(s.id(), GL_TEXTURE_BORDER_COLOR, border);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return s;
}

const char* labelOf(CascadeStorage storage) {
    switch (storage) {
        case CascadeStorage::Array: return "cascade depth array";
        case CascadeStorage::Atlas: return "cascade depth atlas";
        case CascadeStorage::Textures: return "cascade depth texture";
    }
    return "cascade depth";
}
}  // namespace

bool ShadowMaps::Allocation::holds(const csm::StorageLayout& l) const {
    return !textures.empty() && l.storage == layout.storage && l.textures == layout.textures && l.tiles == layout.tiles;
}

void ShadowMaps::ensure(const csm::StorageLayout& layout, MapSet set) {
    Allocation& full = sets_[index(MapSet::Full)];
    Allocation& preview = sets_[index(MapSet::Preview)];
    if (full.holds(layout)) {  // a preview whose maps are the full ones needs no second set
        active_ = index(MapSet::Full);
    } else if (preview.holds(layout)) {
        if (set == MapSet::Full) {  // the full maps are now these: the old full set is stale
            std::swap(full, preview);
            preview = {};
        }
        active_ = index(set);
    } else {
        allocate(sets_[index(set)], layout);
        active_ = index(set);
    }
    if (!fbo_) fbo_ = gpu::createFramebuffer();
    if (!nearest_) nearest_ = compareSampler(GL_NEAREST);
    if (!linear_) linear_ = compareSampler(GL_LINEAR);
    if (!raw_) {
        raw_ = compareSampler(GL_NEAREST);
        glSamplerParameteri(raw_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    }
}

void ShadowMaps::allocate(Allocation& a, const csm::StorageLayout& layout) {
    a.textures.clear();  // freed before the new ones are made: never both in memory
    for (const csm::MapTexture& t : layout.textures) {
        gpu::Texture tex = gpu::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(tex.id(), 1, GL_DEPTH_COMPONENT32F, t.width, t.height, t.layers);
        glObjectLabel(GL_TEXTURE, tex.id(), -1, labelOf(layout.storage));
        // Lit everywhere until drawn: the atlas's padding is never drawn into.
        const float far = 1.0f;
        glClearTexImage(tex.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
        a.textures.push_back(std::move(tex));
    }
    a.layout = layout;
    ++allocations_;
}

GLuint ShadowMaps::texture(int cascade) const { return textureAt(tile(cascade).texture); }

glm::ivec4 ShadowMaps::viewport(int cascade) const {
    const csm::MapTile& t = tile(cascade);
    return {t.x, t.y, t.size, t.size};
}

void ShadowMaps::beginCascade(int cascade, gpu::PassState state) const {
    const csm::MapTile& t = tile(cascade);
    glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, texture(cascade), 0, t.layer);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
    state.framebuffer = fbo_.id();
    state.viewport = viewport(cascade);
    // The scissor keeps the clear (and any draw) inside the tile.
    state.scissor = true;
    state.scissorBox = state.viewport;
    gpu::applyPassState(state);
    glClear(GL_DEPTH_BUFFER_BIT);
}

void ShadowMaps::bindForSampling() const {
    if (layout().storage == CascadeStorage::Textures) {
        for (int i = 0; i < textureCount(); ++i) {
            glBindTextureUnit(ST_BINDING_CASCADE_MAPS + i, textureAt(i));
            glBindSampler(ST_BINDING_CASCADE_MAPS + i, linear_.id());
        }
        return;
    }
    glBindTextureUnit(ST_BINDING_SHADOW_NEAREST, textureAt(0));
    glBindTextureUnit(ST_BINDING_SHADOW_LINEAR, textureAt(0));
    glBindSampler(ST_BINDING_SHADOW_NEAREST, nearest_.id());
    glBindSampler(ST_BINDING_SHADOW_LINEAR, linear_.id());
    glBindTextureUnit(ST_BINDING_SHADOW_RAW, textureAt(0));
    glBindSampler(ST_BINDING_SHADOW_RAW, raw_.id());
}

void ShadowMaps::unbindSamplers() const {
    glBindSampler(ST_BINDING_SHADOW_NEAREST, 0);
    glBindSampler(ST_BINDING_SHADOW_LINEAR, 0);
    glBindSampler(ST_BINDING_SHADOW_RAW, 0);
    for (int i = 0; i < ST_MAX_CASCADES; ++i) glBindSampler(ST_BINDING_CASCADE_MAPS + i, 0);
}

std::vector<float> readCascadeDepth(const ShadowMaps& maps, int cascade) {
    const csm::MapTile& t = maps.tile(cascade);
    std::vector<float> depth(std::size_t(t.size) * std::size_t(t.size));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureSubImage(maps.texture(cascade), 0, t.x, t.y, t.layer, t.size, t.size, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    return depth;
}

}  // namespace st
