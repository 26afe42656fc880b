#pragma once
// UiDriver that renders every frame with ImGui's OpenGL3 backend (from Debian's libimgui.a, with
// its own GL loader) into an offscreen framebuffer; needs a current GL 4.5 context (GLTest).
#include "renderer/gpu/gl.h"
#include "renderer/image/image_io.h"
#include "tests/ui/ui_driver.h"

#include <vector>

namespace st::test {

class GlUiDriver : public UiDriver {
public:
    explicit GlUiDriver(ImVec2 displaySize = {1280.0f, 720.0f});
    ~GlUiDriver() override;

    Rgba8Image screenshot() const;  // the last frame, top row first

    // A size x size RGBA texture with a depth-like gradient and a cascade-numbered stripe
    // pattern, standing in for the app's remapped shadow-map layers. Owned by the driver.
    ImTextureID makeTestTexture(int size, int index);

protected:
    void beginBackendFrame() override;
    void renderDrawData(ImDrawData* data) override;

private:
    int width_;
    int height_;
    gpu::Handle<gpu::deleteTexture> colour_;
    gpu::Handle<gpu::deleteFramebuffer> fbo_;
    std::vector<gpu::Handle<gpu::deleteTexture>> textures_;
};

}  // namespace st::test
