#include "renderer/render/shadow_maps.h"

#include "shaders/interface.h"

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
}  // namespace

void ShadowMaps::ensure(int layers, int size) {
    if (depth_ && layers == layers_ && size == size_) return;
    depth_ = gpu::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
    glObjectLabel(GL_TEXTURE, depth_.id(), -1, "cascade depth array");
    if (!fbo_) fbo_ = gpu::createFramebuffer();
    if (!nearest_) nearest_ = compareSampler(GL_NEAREST);
    if (!linear_) linear_ = compareSampler(GL_LINEAR);
    if (!raw_) {
        raw_ = compareSampler(GL_NEAREST);
        glSamplerParameteri(raw_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    }
    layers_ = layers;
    size_ = size;
}

void ShadowMaps::attachLayer(int layer) const {
    glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0, layer);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
}

void ShadowMaps::bindForSampling() const {
    glBindTextureUnit(ST_BINDING_SHADOW_NEAREST, depth_.id());
    glBindTextureUnit(ST_BINDING_SHADOW_LINEAR, depth_.id());
    glBindSampler(ST_BINDING_SHADOW_NEAREST, nearest_.id());
    glBindSampler(ST_BINDING_SHADOW_LINEAR, linear_.id());
    glBindTextureUnit(ST_BINDING_SHADOW_RAW, depth_.id());
    glBindSampler(ST_BINDING_SHADOW_RAW, raw_.id());
}

}  // namespace st
