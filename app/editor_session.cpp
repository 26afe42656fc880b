#include "app/editor_session.h"

#include "renderer/image/flip_rows.h"
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
    if (opt.preset || fs::exists(presetPath_)) settings_ = loadPreset(presetPath_);  // a bad file given by name fails
    else presetPath_.clear();
    valid_ = settings_;
    loadScene(settings_.scene, {.ground = settings_.ground});
    shadowTiles_ = std::make_unique<ShadowMapView>();
    ui_ = std::make_unique<ui::EditorUi>(opt.presetDir);
    ui_->setDocument(settings_, presetPath_);
    accuracy_ = std::make_unique<EditorAccuracy>();
    scanPresets();
    lastTime_ = glfwGetTime();
}

void EditorSession::scanPresets() {
    presetFiles_.clear();
    std::error_code ec;
    for (const fs::path& dir : {opt_.presetDir, opt_.presetDir / "scenes"})
        for (const auto& e : fs::directory_iterator(dir, ec))
            if (e.path().extension() == ".json") presetFiles_.push_back(e.path());
    std::sort(presetFiles_.begin(), presetFiles_.end());
}

EditorSession::~EditorSession() = default;

void EditorSession::loadScene(const std::string& spec, const SceneOptions& options) {
    try {
        fs::path base = presetPath_.empty() ? opt_.presetDir : presetPath_.parent_path();
        auto scene = std::make_shared<const Scene>(st::loadScene(spec, base, options));
        renderer_.reset();  // the old renderer refers to the old scene
        scene_ = std::move(scene);
        renderer_ = std::make_unique<Renderer>(*scene_);
        loadedScene_ = spec;
        loadedOptions_ = options;
        status_.clear();
    } catch (const std::exception& e) {
        status_ = e.what();
        if (!scene_) throw;  // nothing loaded yet: the session cannot start
        valid_.scene = loadedScene_;  // keep rendering the scene that works; the panel shows why
        valid_.ground = loadedOptions_.ground;
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
    }
    if (swapped_ && !io.WantCaptureMouse) {  // full-window side camera: left mouse orbits, wheel zooms
        if (io.MouseDown[0]) orbit_.yawDeg -= io.MouseDelta.x * 0.3f, orbit_.pitchDeg += io.MouseDelta.y * 0.3f;
        orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, io.MouseWheel), 0.05f, 20.0f);
        return;
    }
    updateFlyCamera(settings_.camera, fly_, in, scene_->wsBounds);
}

void EditorSession::applyRequests(const ui::UiRequests& r) {
    if (r.quit) quit_ = true;
    if (r.frameScene) frameBounds(settings_.camera, scene_->wsBounds);
    if (r.swapSideView) swapped_ = !swapped_;
    if (r.presetsChanged) scanPresets();
    if (r.presetLoaded) presetPath_ = ui_->presetFile();
    orbit_.yawDeg -= r.sideViewOrbit.x * 0.3f;
    orbit_.pitchDeg = std::clamp(orbit_.pitchDeg + r.sideViewOrbit.y * 0.3f, -89.0f, 89.0f);
    orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, r.sideViewZoom), 0.05f, 20.0f);
    pipWidth_ = int(r.sideViewSize.x);
    pipHeight_ = int(r.sideViewSize.y);
    if (r.settingsValid) valid_ = settings_;
    window_.setTitle(ui_->windowTitle());
}

bool EditorSession::renderViews(int width, int height) {
    Settings s = valid_;
    s.output.width = width;
    s.output.height = height;
    if (swapped_) s.output.view = View::Side;
    try {
        stats_ = renderer_->render(s, orbit_);
    } catch (const std::exception& e) {  // settings the math rejects: keep the last image
        status_ = e.what();
        return false;
    }
    {
        // Until the panel reports the size it shows the picture at: a quarter of the window.
        int w = pipWidth_ >= 16 ? pipWidth_ : std::max(16, width / 4);
        int h = pipHeight_ >= 16 ? pipHeight_ : std::max(16, height / 4);
        if (swapped_) h = std::max(16, w * height / width);  // the main view keeps the window's aspect
        retiredPip_ = OffscreenTarget();
        if (w != pip_.width() || h != pip_.height()) retiredPip_ = std::move(pip_);
        pip_.ensure(w, h);
        if (swapped_) renderer_->renderMainView(valid_, pip_);
        else renderer_->renderSideView(valid_, orbit_, pip_);
    }
    // A moment filter's tiles read the frame's cascade block (filter kind, exponents).
    const bool moments = isMomentFilter(valid_.filter.kind);
    if (moments) renderer_->bindShadingInputs();
    shadowTiles_->update(renderer_->shadowMaps(), renderer_->plan(), scene_->wsBounds, 256,
                         moments ? &renderer_->momentMaps() : nullptr);
    return true;
}

// After the render, so a change made this frame (camera keys, a widget) drops the overlay before
// it would be drawn over a view it no longer describes.
void EditorSession::updateAccuracy(const ui::UiRequests& r, bool rendered, int width, int height) {
    Settings s = valid_;  // what the main camera shows, at the scene view's size
    s.output.width = width;
    s.output.height = height;
    accuracy_->update(glfwGetTime(), r.accuracyWanted, rendered, *renderer_, s, scene_);
    if (r.errorOverlay && !swapped_ && accuracy_->overlay())
        ui::drawErrorOverlay(reinterpret_cast<ImTextureID>(std::uintptr_t(accuracy_->overlay())));
}

void EditorSession::present(int width, int height) {
    glBlitNamedFramebuffer(renderer_->framebuffer(), 0, 0, 0, width, height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

ui::UiInputs EditorSession::uiInputs() const {
    auto tex = [](GLuint id) { return reinterpret_cast<ImTextureID>(std::uintptr_t(id)); };
    ui::UiInputs in;
    in.stats = &stats_;
    in.cpuFrameMs = cpuFrameMs_;
    for (int i = 0; i < shadowTiles_->layers(); ++i) {
        in.shadowLayers.push_back(tex(shadowTiles_->layerTexture(i)));
        if (GLuint v = shadowTiles_->varianceTexture(i)) in.shadowVariance.push_back(tex(v));
    }
    in.shadowMapSize = valid_.cascades.mapSize;
    in.sideView = pip_.colorTexture() ? tex(pip_.colorTexture()) : tex(0);
    in.presetFiles = presetFiles_;
    in.statusLine = status_;
    in.accuracy = accuracy_->view();
    return in;
}

void EditorSession::frame(const fs::path* screenshot) {
    auto t0 = std::chrono::steady_clock::now();
    window_.beginFrame();
    if (window_.shouldClose()) {  // the close button asks the panels first (unsaved changes)
        window_.cancelClose();
        ui_->requestQuit();
    }
    handleInput();
    const ui::UiRequests requests = ui_->draw(settings_, uiInputs());
    applyRequests(requests);
    if (const SceneOptions options{.ground = valid_.ground}; valid_.scene != loadedScene_ || options != loadedOptions_)
        loadScene(valid_.scene, options);
    int width = 0, height = 0;
    window_.framebufferSize(width, height);
    if (width >= 16 && height >= 16) {
        const bool rendered = renderViews(width, height);
        updateAccuracy(requests, rendered, width, height);
        present(width, height);
    }
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
    Settings s = valid_;
    s.output.width = renderer_->width();
    s.output.height = renderer_->height();
    savePresetAtomic(s, file);
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
    flipRows(std::span(img.pixels), std::size_t(width) * 4);
    for (std::size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;  // the window is opaque
    writeImageAtomic(file, img);
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), width, height);
}

}  // namespace st::app
