#pragma once
// A picture made on the CPU (RGBA8, top row first) as a texture the editor's panels can show,
// such as the Accuracy panel's error overlay. Texel row 0 holds the picture's top row, so ImGui
// draws it upright with the default uv (0, 0)-(1, 1), unlike rendered targets.
#include "renderer/gpu/gl.h"

#include <cstdint>
#include <vector>

namespace st {

class ImageTexture {
public:
    // Replaces the picture; storage is reallocated only when the size changes. Nearest
    // filtering: the overlay is shown at its own size, pixel for pixel.
    void upload(int width, int height, const std::vector<std::uint8_t>& rgba);
    GLuint id() const { return texture_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    gpu::Texture texture_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace st
