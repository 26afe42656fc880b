#include "app/editor_session.h"

#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace st::app {
namespace fs = std::filesystem;

EditorSession::EditorSession(EditorWindow& window, const EditorOptions& opt) : window_(window), opt_(opt) {
    presetPath_ = opt.preset ? *opt.preset : opt.presetDir / "default.json";
    if (fs::exists(presetPath_) || opt.preset) settings_ = loadPreset(presetPath_);  // a bad file given by name fails
    loadScene(settings_.scene);
    shadowTiles_ = std::make_unique<ShadowMapView>();
    lastTime_ = glfwGetTime();
}

EditorSession::~EditorSession() = default;

void EditorSession::loadScene(const std::string& spec) {
    try {
        auto scene = std::make_unique<Scene>(st::loadScene(spec, presetPath_.parent_path()));
        renderer_.reset();  // the old renderer refers to the old scene
        scene_ = std::move(scene);
        renderer_ = std::make_unique<Renderer>(*scene_);
        loadedScene_ = spec;
        status_.clear();
    } catch (const std::exception& e) {
        status_ = e.what();
        if (!scene_) throw;            // nothing loaded yet: the session cannot start
        settings_.scene = loadedScene_;  // keep the scene that works
    }
}

void EditorSession::handleInput() {
    const ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* w = window_.handle();
    auto key = [w](int k) { return glfwGetKey(w, k) == GLFW_PRESS; };
    FlyInput in;
    in.dt = io.DeltaTime;
    if (!io.WantCaptureMouse) {
        in.mouseDelta = {io.MouseDelta.x, io.MouseDelta.y};
        in.look = io.MouseDown[1];
        in.pan = io.MouseDown[2];
        in.wheel = io.MouseWheel;
    }
    if (!io.WantCaptureKeyboard) {
        in.forward = key(GLFW_KEY_W), in.back = key(GLFW_KEY_S), in.left = key(GLFW_KEY_A);
        in.right = key(GLFW_KEY_D), in.down = key(GLFW_KEY_Q), in.up = key(GLFW_KEY_E);
        in.frameScene = ImGui::IsKeyPressed(GLFW_KEY_F, false);
        if (ImGui::IsKeyPressed(GLFW_KEY_TAB, false)) swapped_ = !swapped_;
    }
    if (swapped_ && !io.WantCaptureMouse) {  // the side camera orbits with the left mouse button
        if (io.MouseDown[0]) orbit_.yawDeg -= io.MouseDelta.x * 0.3f, orbit_.pitchDeg += io.MouseDelta.y * 0.3f;
        orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, io.MouseWheel), 0.05f, 20.0f);
        return;
    }
    updateFlyCamera(settings_.camera, fly_, in, scene_->wsBounds);
}

void EditorSession::renderViews(int width, int height) {
    Settings s = settings_;
    s.output.width = width;
    s.output.height = height;
    if (swapped_) s.output.view = View::Side;
    try {
        stats_ = renderer_->render(s, orbit_);
    } catch (const std::exception& e) {  // settings the math rejects: keep the last image
        status_ = e.what();
        return;
    }
    pip_.ensure(std::max(width / 4, 16), std::max(height / 4, 16));
    if (swapped_) renderer_->renderMainView(settings_, pip_);
    else renderer_->renderSideView(settings_, orbit_, pip_);
    shadowTiles_->update(renderer_->shadowMaps(), renderer_->plan(), scene_->wsBounds, 256);
}

void EditorSession::present(int width, int height) {
    glBlitNamedFramebuffer(renderer_->framebuffer(), 0, 0, 0, width, height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
    int x0 = width - pip_.width() - 8, y0 = 8;  // bottom-right corner (GL origin is bottom-left)
    glBlitNamedFramebuffer(pip_.framebuffer(), 0, 0, 0, pip_.width(), pip_.height(), x0, y0, x0 + pip_.width(),
                           y0 + pip_.height(), GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

void EditorSession::drawPanels() {
    ImGui::Begin("Frame");
    ImGui::Text("CPU frame %.1f ms", cpuFrameMs_);
    ImGui::Text("GPU shadow %.2f ms, main %.2f ms", stats_.gpuShadowMs, stats_.gpuMainMs);
    for (std::size_t i = 0; i < stats_.cascades.size(); ++i)
        ImGui::Text("cascade %zu: %.1f-%.1f m, texel %.3f m, %d draws", i, stats_.cascades[i].vsNear,
                    stats_.cascades[i].vsFar, stats_.cascades[i].texelWorldSize, stats_.cascades[i].casterDraws);
    for (int i = 0; i < shadowTiles_->layers(); ++i) {
        ImGui::Image(reinterpret_cast<ImTextureID>(std::uintptr_t(shadowTiles_->layerTexture(i))), ImVec2(96, 96));
        if (i + 1 < shadowTiles_->layers()) ImGui::SameLine();
    }
    if (!status_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", status_.c_str());
    ImGui::End();
}

void EditorSession::frame(const fs::path* screenshot) {
    auto t0 = std::chrono::steady_clock::now();
    window_.beginFrame();
    handleInput();
    if (settings_.scene != loadedScene_) loadScene(settings_.scene);
    int width = 0, height = 0;
    window_.framebufferSize(width, height);
    if (width >= 16 && height >= 16) {
        renderViews(width, height);
        present(width, height);
    }
    drawPanels();
    window_.endFrame();
    if (screenshot) writeScreenshot(*screenshot, width, height);
    window_.swapBuffers();
    cpuFrameMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    frameMs_.push_back(cpuFrameMs_);
}

void EditorSession::writeSceneShot(const fs::path& file) const {
    writeImageAtomic(file, {renderer_->width(), renderer_->height(), renderer_->readRgba8()});
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), renderer_->width(), renderer_->height());
}

void EditorSession::saveAs(const fs::path& file) {
    settings_.output.width = renderer_->width();
    settings_.output.height = renderer_->height();
    savePresetAtomic(settings_, file);
    presetPath_ = file;
    std::printf("saved %s\n", file.string().c_str());
}

void EditorSession::printFrameTimes() const {
    if (frameMs_.size() < 3) return;
    std::vector<double> t(frameMs_.begin() + 1, frameMs_.end());  // the first frame compiles shaders
    std::sort(t.begin(), t.end());
    double median = t[t.size() / 2];
    std::printf("%zu frames, median frame %.1f ms (%.1f fps)\n", t.size(), median, 1000.0 / median);
}

void EditorSession::writeScreenshot(const fs::path& file, int width, int height) {
    Rgba8Image img{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(img.pixels.begin() + y * row, img.pixels.begin() + (y + 1) * row,
                         img.pixels.begin() + (height - 1 - y) * row);
    for (std::size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;  // the window is opaque
    writeImageAtomic(file, img);
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), width, height);
}

}  // namespace st::app
