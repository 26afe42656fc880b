#include "renderer/render/present.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/image/flip_rows.h"

namespace st {

void blitColor(GLuint from, const PixelRect& src, GLuint to, const PixelRect& dst, BlitFilter filter) {
    glBlitNamedFramebuffer(from, to, src.x, src.y, src.x + src.width, src.y + src.height, dst.x, dst.y,
                           dst.x + dst.width, dst.y + dst.height, GL_COLOR_BUFFER_BIT,
                           filter == BlitFilter::Linear ? GL_LINEAR : GL_NEAREST);
}

void clearWindow(const glm::vec4& color) {
    const GLfloat rgba[4] = {color.r, color.g, color.b, color.a};
    glClearNamedFramebufferfv(0, GL_COLOR, 0, rgba);
}

std::vector<std::uint8_t> readWindowRgba8(int width, int height) {
    std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    flipRows(std::span(pixels), std::size_t(width) * 4);
    return pixels;
}

void bindWindowForOverlay(int width, int height) {
    gpu::PassState ui;
    ui.viewport = {0, 0, width, height};
    gpu::applyPassState(ui);
}

}  // namespace st
