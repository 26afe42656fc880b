#include "renderer/render/moment_maps.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/render/shader_library.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace st {
namespace {
int mipLevels(bool mipmaps, int size) { return mipmaps ? std::bit_width(static_cast<unsigned>(size)) : 1; }

gpu::Sampler momentSampler(GLenum minFilter) {
    gpu::Sampler s = gpu::createSampler();
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, minFilter);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, minFilter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
    // The rim texel continues past the map: a kernel reading outside sees the cascade's own edge.
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return s;
}
}  // namespace

MomentFormat momentFormat(FilterKind kind, bool sixteenBit) {
    switch (kind) {
        case FilterKind::Vsm:
        case FilterKind::Evsm2: return sixteenBit ? MomentFormat{GL_RG16F, 4} : MomentFormat{GL_RG32F, 8};
        case FilterKind::Evsm4: return sixteenBit ? MomentFormat{GL_RGBA16F, 8} : MomentFormat{GL_RGBA32F, 16};
        case FilterKind::Msm: return sixteenBit ? MomentFormat{GL_RGBA16, 8} : MomentFormat{GL_RGBA32F, 16};
        default: break;
    }
    throw std::logic_error("filter kind " + std::to_string(int(kind)) + " has no moment map");
}

std::size_t momentMapBytes(FilterKind kind, bool sixteenBit, bool mipmaps, int layers, int size) {
    const auto texel = static_cast<std::size_t>(momentFormat(kind, sixteenBit).bytesPerTexel);
    std::size_t bytes = 0;
    for (int level = 0, s = size; level < mipLevels(mipmaps, size); ++level, s = std::max(s / 2, 1))
        bytes += texel * static_cast<std::size_t>(s) * static_cast<std::size_t>(s) * static_cast<std::size_t>(layers);
    return bytes + 16u * static_cast<std::size_t>(size) * static_cast<std::size_t>(size);  // RGBA32F scratch
}

MomentMaps::MomentMaps() {
    makeProgram_ = sharedShaderProgram("fullscreen.vert", "moments_make.frag", "moments_make");
    blurProgram_ = sharedShaderProgram("fullscreen.vert", "moments_blur.frag", "moments_blur");
    emptyVao_ = gpu::createVertexArray();
    fbo_ = gpu::createFramebuffer();
    raw_ = momentSampler(GL_NEAREST);
    linear_ = momentSampler(GL_LINEAR);
    trilinear_ = momentSampler(GL_LINEAR_MIPMAP_LINEAR);
}

void MomentMaps::ensure(const Settings& s, int layers, int size) {
    const FilterKind kind = s.filter.kind;
    const bool same = moments_ && layers == layers_ && size == size_ && s.filter.moments16 == sixteen_ &&
                      s.filter.mipmaps == mipmaps_ && momentFormat(kind, sixteen_).internalFormat ==
                                                          momentFormat(kind_, sixteen_).internalFormat;
    kind_ = kind;
    if (same) return;
    sixteen_ = s.filter.moments16;
    mipmaps_ = s.filter.mipmaps;
    moments_ = gpu::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(moments_.id(), mipLevels(mipmaps_, size), momentFormat(kind, sixteen_).internalFormat, size,
                       size, layers);
    glObjectLabel(GL_TEXTURE, moments_.id(), -1, "cascade moment array");
    if (size != size_ || !scratch_) {
        scratch_ = gpu::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(scratch_.id(), 1, GL_RGBA32F, size, size);
        glObjectLabel(GL_TEXTURE, scratch_.id(), -1, "moment blur scratch");
    }
    layers_ = layers;
    size_ = size;
}

void MomentMaps::build(const ShadowMaps& depth, const Settings& s) {
    gpu::DebugGroup group("moment maps");
    // One layer per cascade of one array (validation refuses moment filters with other storage).
    if (depth.layout().storage != CascadeStorage::Array)
        throw std::logic_error("moment maps need cascades.storage \"array\"");
    ensure(s, depth.cascades(), depth.tile(0).size);
    gpu::PassState state;
    state.framebuffer = fbo_.id();
    state.viewport = {0, 0, size_, size_};
    gpu::applyPassState(state);
    glBindVertexArray(emptyVao_.id());
    glBindTextureUnit(ST_BINDING_MOMENT_SOURCE, depth.texture(0));
    glBindSampler(ST_BINDING_MOMENT_SOURCE, raw_.id());
    glBindTextureUnit(ST_BINDING_MOMENT_SCRATCH, scratch_.id());
    glBindSampler(ST_BINDING_MOMENT_SCRATCH, raw_.id());
    overlay_.bind(ST_BLOCK_OVERLAY);
    for (int i = 0; i < layers_; ++i) {
        gpu_if::OverlayBlock b;
        b.layer = i;
        overlay_.upload(b);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, scratch_.id(), 0);
        glNamedFramebufferDrawBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
        glUseProgram(makeProgram_->id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glNamedFramebufferTextureLayer(fbo_.id(), GL_COLOR_ATTACHMENT0, moments_.id(), 0, i);
        glUseProgram(blurProgram_->id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    // The scratch texture is a framebuffer attachment no more once the last layer is written.
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
    glBindSampler(ST_BINDING_MOMENT_SOURCE, 0);
    glBindSampler(ST_BINDING_MOMENT_SCRATCH, 0);
    if (mipmaps_) glGenerateTextureMipmap(moments_.id());
}

void MomentMaps::bindForSampling() const {
    glBindTextureUnit(ST_BINDING_MOMENTS, moments_.id());
    glBindSampler(ST_BINDING_MOMENTS, mipmaps_ ? trilinear_.id() : linear_.id());
}

PassWork MomentMaps::buildWork(int blurRadius) const {
    const std::uint64_t texels = std::uint64_t(size_) * std::uint64_t(size_) * std::uint64_t(layers_);
    const std::uint64_t taps = 2u * std::uint64_t(blurRadius) + 1u;
    const auto texel = std::uint64_t(momentFormat(kind_, sixteen_).bytesPerTexel);
    constexpr std::uint64_t kScratch = 16;  // RGBA32F
    PassWork w;
    w.draws = 2u * std::uint64_t(layers_);
    w.filterTaps = 2u * texels * taps;
    w.bytesRead = texels * taps * (4u + kScratch);
    w.bytesWritten = texels * (kScratch + texel);
    if (mipmaps_) {
        const std::uint64_t all = momentMapBytes(kind_, sixteen_, true, layers_, size_) - kScratch * std::uint64_t(size_) * std::uint64_t(size_);
        const std::uint64_t level0 = texels * texel;
        const std::uint64_t last = texel * std::uint64_t(layers_);  // the 1x1 level is read by none
        w.bytesWritten += all - level0;
        w.bytesRead += all - last;
    }
    return w;
}

std::size_t MomentMaps::bytes() const { return momentMapBytes(kind_, sixteen_, mipmaps_, layers_, size_); }

int MomentMaps::components() const { return kind_ == FilterKind::Vsm || kind_ == FilterKind::Evsm2 ? 2 : 4; }

}  // namespace st
