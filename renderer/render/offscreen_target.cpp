#include "renderer/render/offscreen_target.h"

#include "renderer/image/flip_rows.h"

namespace st {

void OffscreenTarget::ensure(int width, int height) {
    if (color_ && width == width_ && height == height_) return;
    color_ = gpu::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(color_.id(), 1, GL_RGBA8, width, height);
    depth_ = gpu::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
    if (!fbo_) fbo_ = gpu::createFramebuffer();
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    width_ = width;
    height_ = height;
}

void OffscreenTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> OffscreenTarget::readRgba8() const {
    std::vector<std::uint8_t> pixels(std::size_t(width_) * height_ * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(pixels.size()), pixels.data());
    flipRows(std::span(pixels), std::size_t(width_) * 4);
    return pixels;
}

}  // namespace st
