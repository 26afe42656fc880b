#pragma once
// The moment maps of the moment filters (FilterKind::Vsm..Msm): one layer per cascade, made from
// the depth array after the shadow pass by two fullscreen passes per layer (moments of each
// texel blurred along x into a float scratch texture, then along y into the layer: a separable
// Gaussian, seed 004 "VSMs with CSMs"), then optionally mipmapped. Array layout only.
#include "renderer/gpu/gl.h"
#include "renderer/render/shader_library.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/pass_work.h"
#include "renderer/render/shadow_maps.h"
#include "renderer/settings/settings.h"
#include "shaders/interface.h"

#include <cstddef>

namespace st {

// What the moment array of a filter stores (kind must be a moment filter).
struct MomentFormat {
    GLenum internalFormat = GL_NONE;  // RG32F/RG16F (VSM, EVSM2), RGBA32F/RGBA16F (EVSM4), RGBA16 (MSM 16)
    int bytesPerTexel = 0;
};
MomentFormat momentFormat(FilterKind kind, bool sixteenBit);

// Bytes of the moment array (every layer, every mip level) and the scratch texture.
std::size_t momentMapBytes(FilterKind kind, bool sixteenBit, bool mipmaps, int layers, int size);

class MomentMaps {
public:
    MomentMaps();  // needs a current GL context: links the two passes' programs

    // Rebuilds the moments of every layer of `depth` for s.filter. Reads the cascade block bound
    // at ST_BLOCK_CASCADES (filter kind, blur radius, exponents).
    void build(const ShadowMaps& depth, const Settings& s);
    void bindForSampling() const;  // ST_BINDING_MOMENTS, linear (trilinear with mipmaps)
    // The renderer's own counts of the last build() with that blur radius: per layer two
    // fullscreen draws of size^2 fragments, 2r + 1 fetches each (depth, then the RGBA32F
    // scratch), the scratch and the layer written; with mipmaps each level read once and the
    // next written.
    PassWork buildWork(int blurRadius) const;
    GLuint texture() const { return moments_.id(); }
    std::size_t bytes() const;
    int layers() const { return layers_; }
    int size() const { return size_; }
    int components() const;  // 2 or 4
    FilterKind kind() const { return kind_; }

private:
    void ensure(const Settings& s, int layers, int size);
    SharedProgram makeProgram_;
    SharedProgram blurProgram_;
    gpu::VertexArray emptyVao_;
    gpu::Framebuffer fbo_;
    gpu::Texture moments_;
    gpu::Texture scratch_;
    gpu::Sampler raw_;
    gpu::Sampler linear_;
    gpu::Sampler trilinear_;
    gpu::UniformBuffer<gpu_if::OverlayBlock> overlay_;
    FilterKind kind_ = FilterKind::Vsm;
    bool sixteen_ = false;
    bool mipmaps_ = false;
    int layers_ = 0;
    int size_ = 0;
};

}  // namespace st
