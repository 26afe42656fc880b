#pragma once
// The cascades' depth texture array (D32F, one layer per cascade) with its framebuffer and the two
// compare samplers. Reallocated only when the layer count or size changes.
#include "renderer/csm/limits.h"
#include "renderer/gpu/gl.h"

#include <cstddef>

namespace st {

class ShadowMaps {
public:
    void ensure(int layers, int size);  // (re)allocates when layers or size differ
    void attachLayer(int layer) const;  // as the depth attachment of framebuffer()
    GLuint framebuffer() const { return fbo_.id(); }
    // The array on both shadow bindings (nearest + linear compare) and, raw, on ST_BINDING_SHADOW_RAW.
    void bindForSampling() const;
    GLuint texture() const { return depth_.id(); }
    int layers() const { return layers_; }
    int size() const { return size_; }
    std::size_t bytes() const { return csm::shadowMapBytes(layers_, size_); }

private:
    gpu::Texture depth_;
    gpu::Framebuffer fbo_;
    gpu::Sampler nearest_;
    gpu::Sampler linear_;
    gpu::Sampler raw_;
    int layers_ = 0;
    int size_ = 0;
};

}  // namespace st
