#pragma once
// Putting frames on a window: colour copied between framebuffers (0 is the window's), the
// window cleared and read back, and the state the UI backend draws over it with. Here so that
// app/ makes no GL calls of its own.
#include "renderer/gpu/gl.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace st {

struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

enum class BlitFilter { Nearest, Linear };

// Colour of `src` in `from` into `dst` in `to`, scaled when the sizes differ.
void blitColor(GLuint from, const PixelRect& src, GLuint to, const PixelRect& dst, BlitFilter filter = BlitFilter::Nearest);

void clearWindow(const glm::vec4& color);

// The window's back buffer, width x height RGBA8 from the bottom-left corner, top row first.
std::vector<std::uint8_t> readWindowRgba8(int width, int height);

// The window's framebuffer with a width x height viewport and every pass state reset (no depth,
// no culling), for the UI backend, which sets blending and scissoring itself.
void bindWindowForOverlay(int width, int height);

}  // namespace st
