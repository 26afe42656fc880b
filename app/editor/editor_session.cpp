#include "app/editor/editor_session.h"

#include "app/editor/layout_file.h"
#include "app/scene_preset.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace st::app {
namespace fs = std::filesystem;

EditorSession::EditorSession(EditorWindow& window, const EditorOptions& opt)
    : window_(window),
      opt_(opt),
      model_(std::make_unique<EditorModel>(ModelOptions{opt.preset, opt.presetDir, {}})),
      viewport_(std::make_unique<ViewportRenderer>(*model_)) {
    const fs::path layout = window_.configDir() / "layout.json";
    model_->ui().setLayoutPrefs(fs::exists(layout) ? loadLayoutPrefs(layout) : ui::scaledDefaults(window_.uiScale()));
    model_->ui().setEngine(opt.engine);
    model_->ui().setErrorOverlay(opt.errorOverlay);
}

EditorSession::~EditorSession() { saveLayoutPrefs(window_.configDir() / "layout.json", model_->ui().layoutPrefs()); }

CameraInput EditorSession::cameraInput() const {
    const ImGuiIO& io = ImGui::GetIO();
    auto key = [w = window_.handle()](int k) { return glfwGetKey(w, k) == GLFW_PRESS; };
    CameraInput in;
    // After a wait for events the frame's time step spans the wait: the fly takes at most a
    // quarter second of it, so the first step of a key pressed after a pause is not a leap.
    in.fly.dt = std::min(io.DeltaTime, 0.25f);
    in.overScene = !io.WantCaptureMouse;
    if (in.overScene) {
        in.mouseDelta = in.fly.mouseDelta = {io.MouseDelta.x, io.MouseDelta.y};
        in.fly.look = io.MouseDown[1];
        in.fly.pan = io.MouseDown[2];
        in.wheel = in.fly.wheel = io.MouseWheel;
        in.altClick = io.KeyAlt && io.MouseClicked[0];
    }
    in.leftDown = io.MouseDown[0];
    if (!io.WantCaptureKeyboard) {
        in.fly.forward = key(GLFW_KEY_W), in.fly.back = key(GLFW_KEY_S), in.fly.left = key(GLFW_KEY_A);
        in.fly.right = key(GLFW_KEY_D), in.fly.down = key(GLFW_KEY_Q), in.fly.up = key(GLFW_KEY_E);
    }
    const glm::vec3 target = model_->settings().camera.target;
    if (in.altClick && !model_->swapped())  // the orbit's pivot: the surface under the cursor
        in.pivot = viewport_->pickedPoint(io.MousePos, model_->scenePos(), io.DisplayFramebufferScale, target);
    in.scriptedOrbitDeg = opt_.orbitDegPerFrame;
    in.seconds = glfwGetTime();
    return in;
}

ViewportFrame EditorSession::viewportFrame(bool final) const {
    ViewportFrame f = asked_;
    f.time = glfwGetTime();
    window_.framebufferSize(f.fbWidth, f.fbHeight);
    f.fbScale = ImGui::GetIO().DisplayFramebufferScale;
    f.lastFrameMs = lastFrameMs_;
    f.final = final;
    return f;
}

void EditorSession::fillUiInputs(ui::UiInputs& in) const {
    viewport_->fillUiInputs(in, *model_);
    in.cpuFrameMs = lastFrameMs_;
    in.presetFiles = model_->presetFiles();
    in.statusLine = model_->message();
    in.checkScene = [m = model_.get()](const std::string& spec, bool ground, const fs::path& baseDir) {
        return m->checkScene(spec, ground, baseDir);
    };
    in.presetForScene = [](const fs::path& gltf) { return presetForScene(gltf, {}); };
    in.sweep = &model_->sweep().view();
    in.sweepableFields = model_->sweepableFields();
    in.tune = &model_->tune().view();
    in.tuneObjectives = model_->tuneObjectives();
    in.motion = model_->motionView();
}

void EditorSession::frame(const fs::path* screenshot, bool final) {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = processCpuMs();
    if (opt_.hover.size() == 2) {  // scripted: the pointer rests there, as a user's would
        if (times_.frames() == 0) glfwFocusWindow(window_.handle());
        glfwSetCursorPos(window_.handle(), opt_.hover[0], opt_.hover[1]);
    }
    window_.beginFrame();
    const unsigned long events = window_.eventCount();
    bool newEvents = events != lastEvents_ || window_.inputQueued();
    lastEvents_ = events;
    model_->applyCamera(cameraInput());  // input -> model
    if (opt_.previewPath && times_.frames() == 1) model_->startPreview();  // scripted: once the panels are placed
    model_->poll();
    SceneRender scene = viewport_->frame(*model_, viewportFrame(final));  // render
    ui::UiInputs in;
    fillUiInputs(in);
    const ui::UiRequests requests = model_->drawPanels(in);  // UI
    model_->apply(requests);                                 // requests -> model
    // The close button or Ctrl+C asks the panels (unsaved changes) once the input queued before it
    // has landed and been drawn: a Save clicked just before Ctrl+C is saved, not asked about.
    if (window_.closeAskedAtPoll() && !window_.inputQueued()) {
        newEvents = true;  // Ctrl+C is no GLFW event: the frames that answer it must follow
        window_.cancelClose();
        model_->requestQuit();
    }
    asked_.accuracyWanted = requests.accuracyWanted, asked_.errorOverlay = requests.errorOverlay;
    asked_.probeWanted = requests.probeWanted, asked_.probePixel = requests.probePixel;
    // The first frame learns where the scene goes from the panels: it renders after them.
    if (!scene.rendered && !scene.reused) scene = viewport_->frame(*model_, viewportFrame(final));
    if (scene.rendered) times_.sceneRender(scene.ms, scene.scale);
    if (scene.reused) times_.sceneReused();
    window_.setTitle(model_->ui().windowTitle());
    window_.endFrame();
    int width = 0, height = 0;
    window_.framebufferSize(width, height);
    if (screenshot) writeWindowShot(*screenshot, width, height);
    window_.swapBuffers();
    lastFrameMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    times_.frame(lastFrameMs_, processCpuMs() - cpu0);
    noteActivity(newEvents, scene.rendered, requests);
}

void EditorSession::noteActivity(bool events, bool sceneRendered, const ui::UiRequests& r) {
    std::string shown = model_->shownState() + '\n' + viewport_->shownState();
    activity_.events = events;
    activity_.changed = sceneRendered || r.change != ChangeClass::None || shown != lastShown_;
    lastShown_ = std::move(shown);
    // A held key repeats (ImGui's key repeat, the fly's WASD) and a held button may repeat (a
    // step button) or drag: both act without new events. A scripted orbit turns every frame.
    const ImGuiIO& io = ImGui::GetIO();
    bool keyDown = false;  // a modifier held alone does nothing by itself
    for (int k = 0; k < IM_ARRAYSIZE(io.KeysDown); ++k)
        keyDown |= io.KeysDown[k] && (k < GLFW_KEY_LEFT_SHIFT || k > GLFW_KEY_RIGHT_SUPER);
    const bool buttonDown = std::find(std::begin(io.MouseDown), std::end(io.MouseDown), true) != std::end(io.MouseDown);
    activity_.animating = keyDown || buttonDown || opt_.orbitDegPerFrame != 0.0f || model_->preview().active();
    activity_.jobRunning = viewport_->jobRunning(*model_) || model_->sweep().running() || model_->tune().running();
}

void EditorSession::saveAs(const fs::path& file) {
    model_->savePresetAs(file, viewport_->imageWidth(), viewport_->imageHeight());
    std::printf("saved %s\n", file.string().c_str());
}

void EditorSession::writeLayoutReport(const fs::path& file) const {
    const ImGuiIO& io = ImGui::GetIO();
    app::writeLayoutReport(file, model_->ui().itemRects(), io.DisplaySize, model_->scenePos(), model_->sceneSize());
}

}  // namespace st::app
