#include "tests/ui/ui_gl_driver.h"

#include "renderer/image/flip_rows.h"

#include <backends/imgui_impl_opengl3.h>

#include <cstdint>
#include <stdexcept>

namespace st::test {

GlUiDriver::GlUiDriver(ImVec2 displaySize)
    : UiDriver(displaySize), width_(static_cast<int>(displaySize.x)), height_(static_cast<int>(displaySize.y)) {
    if (!ImGui_ImplOpenGL3_Init("#version 450")) throw std::runtime_error("ImGui_ImplOpenGL3_Init failed");
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    colour_ = gpu::Handle<gpu::deleteTexture>(id);
    glTextureStorage2D(id, 1, GL_RGBA8, width_, height_);
    glCreateFramebuffers(1, &id);
    fbo_ = gpu::Handle<gpu::deleteFramebuffer>(id);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, colour_.id(), 0);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("UI test framebuffer is incomplete");
    }
}

GlUiDriver::~GlUiDriver() { ImGui_ImplOpenGL3_Shutdown(); }

void GlUiDriver::beginBackendFrame() { ImGui_ImplOpenGL3_NewFrame(); }

void GlUiDriver::renderDrawData(ImDrawData* data) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glClearColor(0.18f, 0.22f, 0.27f, 1.0f);  // stands in for the scene behind the panels
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(data);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Rgba8Image GlUiDriver::screenshot() const {
    Rgba8Image image{width_, height_, std::vector<std::uint8_t>(static_cast<std::size_t>(width_ * height_ * 4))};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(colour_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.pixels.size()),
                      image.pixels.data());
    flipRows(std::span(image.pixels), static_cast<std::size_t>(width_) * 4);
    return image;
}

ImTextureID GlUiDriver::makeTestTexture(int size, int index) {
    std::vector<std::uint8_t> texels(static_cast<std::size_t>(size * size * 4));
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const auto depth = static_cast<std::uint8_t>(255 * (x + y) / (2 * size));
            const bool stripe = ((x / 8) % (index + 2)) == 0 && y < size / 2;  // rows 0.. = bottom in GL
            std::uint8_t* t = &texels[static_cast<std::size_t>((y * size + x) * 4)];
            t[0] = t[1] = t[2] = stripe ? std::uint8_t{20} : depth;
            t[3] = 255;
        }
    }
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, 1, GL_RGBA8, size, size);
    glTextureSubImage2D(id, 0, 0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    textures_.emplace_back(id);
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(id));
}

}  // namespace st::test
