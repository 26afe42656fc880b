#pragma once
// A colour (RGBA8) + depth (D32F) framebuffer of a given size, reallocated only on resize.
#include "renderer/gpu/gl.h"

#include <cstdint>
#include <vector>

namespace st {

class OffscreenTarget {
public:
    void ensure(int width, int height);
    void bind() const;  // as the draw framebuffer, with a matching viewport
    std::vector<std::uint8_t> readRgba8() const;  // width*height*4, top row first
    GLuint framebuffer() const { return fbo_.id(); }
    GLuint colorTexture() const { return color_.id(); }
    GLuint depthTexture() const { return depth_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    gpu::Texture color_;
    gpu::Texture depth_;
    gpu::Framebuffer fbo_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace st
