#include "app/editor_session.h"

#include "app/cost_profile_file.h"

#include "app/preset_list.h"
#include "app/layout_file.h"
#include "app/side_split_handles.h"
#include "renderer/image/image_io.h"
#include "renderer/render/device.h"
#include "renderer/render/present.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_spec.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace st::app {
namespace fs = std::filesystem;

EditorSession::EditorSession(EditorWindow& window, const EditorOptions& opt)
    : window_(window), opt_(opt), costProfile_(loadCostProfileOption("")) {
    presetPath_ = opt.preset ? *opt.preset : opt.presetDir / "default.json";
    if (opt.preset || fs::exists(presetPath_)) settings_ = loadPreset(presetPath_);  // a bad file given by name fails
    else presetPath_.clear();
    valid_ = settings_;
    loadScene(settings_.scene, {.ground = settings_.ground});
    shadowTiles_ = std::make_unique<ShadowMapView>();
    ui_ = std::make_unique<ui::EditorUi>(opt.presetDir);
    ui_->setDocument(settings_, presetPath_);
    ui_->setLayoutPrefs(loadLayoutPrefs(window_.configDir() / "layout.json"));
    accuracy_ = std::make_unique<EditorAccuracy>();
    std::error_code ec;
    sweep_ = std::make_unique<EditorSweep>(fs::read_symlink("/proc/self/exe", ec));  // this binary's `sweep`
    tune_ = std::make_unique<EditorTune>(fs::read_symlink("/proc/self/exe", ec));    // ... and its `tune`
    for (const FieldInfo& field : fieldTable())
        if (sweep::isSweepable(field)) sweepable_.emplace_back(field.path);
    scanPresets();
    lastTime_ = glfwGetTime();
}

void EditorSession::scanPresets() {
    presetFiles_ = listPresetFiles(opt_.presetDir);
}

EditorSession::~EditorSession() { saveLayoutPrefs(window_.configDir() / "layout.json", ui_->layoutPrefs()); }

fs::path EditorSession::sceneBase() const { return presetPath_.empty() ? opt_.presetDir : folderOf(presetPath_); }

void EditorSession::loadScene(const std::string& spec, const SceneOptions& options) {
    try {
        const std::string key = sceneKey(spec, sceneBase(), options);
        auto scene = key == preparedKey_ ? prepared_ : std::make_shared<const Scene>(st::loadScene(spec, sceneBase(), options));
        prepared_.reset(), preparedKey_.clear();
        renderer_.reset();  // the old renderer refers to the old scene
        scene_ = std::move(scene);
        renderer_ = std::make_unique<Renderer>(*scene_);
        ++rendererGeneration_;
        loadedScene_ = spec;
        loadedKey_ = key;
        loadedOptions_ = options;
        status_.clear();
    } catch (const std::exception& e) {
        status_ = e.what();
        if (!scene_) throw;  // nothing loaded yet: the session cannot start
        valid_.scene = loadedScene_;  // keep rendering the scene that works; the panel shows why
        valid_.ground = loadedOptions_.ground;
    }
}

// Loads the scene the panels are about to choose, so a file that does not load is refused before
// it reaches the document (issue 13 #1); the scene loaded is kept for loadScene.
std::string EditorSession::checkScene(const std::string& spec, bool ground, const fs::path& baseDir) {
    const SceneOptions options{.ground = ground};
    const std::string key = sceneKey(spec, baseDir, options);
    if (key == loadedKey_ || key == preparedKey_) return {};
    try {
        prepared_ = std::make_shared<const Scene>(st::loadScene(spec, baseDir, options));
        preparedKey_ = key;
        return {};
    } catch (const std::exception& e) {
        return e.what();
    }
}

void EditorSession::handleInput() {
    const ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* w = window_.handle();
    auto key = [w](int k) { return glfwGetKey(w, k) == GLFW_PRESS; };
    FlyInput in;
    // After a wait for events the frame's time step spans the wait: the fly takes at most a
    // quarter second of it, so the first step of a key pressed after a pause is not a leap.
    in.dt = std::min(io.DeltaTime, 0.25f);
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
    const CameraSettings before = settings_.camera;
    // Alt + left drag orbits the main camera around the point under the cursor where it began.
    if (!swapped_ && !io.WantCaptureMouse && io.KeyAlt && io.MouseClicked[0]) {
        orbiting_ = true;
        orbitPivot_ = pickedPoint(io.MousePos);
    }
    if (swapped_ && !io.WantCaptureMouse) {  // full-window side camera: left mouse orbits, wheel zooms
        if (io.MouseDown[0]) orbit_.yawDeg -= io.MouseDelta.x * 0.3f, orbit_.pitchDeg += io.MouseDelta.y * 0.3f;
        orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, io.MouseWheel), 0.05f, 20.0f);
    } else if (orbiting_) {
        orbitCamera(settings_.camera, orbitPivot_, {io.MouseDelta.x, io.MouseDelta.y});
        // Ended after its movement is taken: the mouse queue may put the last moves and the
        // release in one frame, and that frame's movement belongs to the drag.
        if (!io.MouseDown[0]) orbiting_ = false;
    } else if (in.look || in.pan || in.wheel != 0.0f) {
        // Only then: re-deriving the target from the position each frame drifts by rounding,
        // and every drift would be an undo step.
        updateFlyCamera(settings_.camera, fly_, in, scene_->wsBounds);
    }
    // A fly or pan gesture is one undo step (issue 13 #4).
    if (auto start = cameraGesture_.update(before, settings_.camera, in.look || in.pan || orbiting_)) {
        Settings atStart = settings_;
        atStart.camera = *start;
        ui_->recordEdit(atStart, settings_);
    }
    if (opt_.orbitDegPerFrame != 0.0f) {  // scripted: no gesture, no undo step, as a benchmark's camera path
        const float a = glm::radians(opt_.orbitDegPerFrame), c = std::cos(a), sn = std::sin(a);
        const glm::vec3 d = settings_.camera.position - settings_.camera.target;
        settings_.camera.position = settings_.camera.target + glm::vec3(c * d.x + sn * d.z, d.y, -sn * d.x + c * d.z);
    }
}

// The surface point under `mouse` (display pixels) in the probe's last read-back, else the
// camera's target: the orbit's pivot.
glm::vec3 EditorSession::pickedPoint(ImVec2 mouse) const {
    const MeasureSamples* m = probe_.samples();
    const ImGuiIO& io = ImGui::GetIO();
    const int x = int(std::floor((mouse.x - scenePos_.x) * io.DisplayFramebufferScale.x));
    const int y = int(std::floor((mouse.y - scenePos_.y) * io.DisplayFramebufferScale.y));
    if (!m || x < 0 || y < 0 || x >= m->width || y >= m->height) return settings_.camera.target;
    const std::size_t i = std::size_t(y) * std::size_t(m->width) + std::size_t(x);
    return m->covered(i) ? glm::vec3(m->position[i]) : settings_.camera.target;
}

void EditorSession::applyRequests(const ui::UiRequests& r) {
    if (r.quit) quit_ = true;
    if (r.frameScene) {  // moves the camera only, as one undo step; near/far are tuning settings
        const Settings before = settings_;
        status_ = frameKeepingClipPlanes(settings_.camera, scene_->wsBounds);
        ui_->recordEdit(before, settings_);
    }
    if (r.swapSideView) swapped_ = !swapped_;
    if (r.presetsChanged) scanPresets();
    presetPath_ = ui_->presetFile();  // a load or a save may have moved the document
    orbit_.yawDeg -= r.sideViewOrbit.x * 0.3f;
    orbit_.pitchDeg = std::clamp(orbit_.pitchDeg + r.sideViewOrbit.y * 0.3f, -89.0f, 89.0f);
    orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, r.sideViewZoom), 0.05f, 20.0f);
    placeScene(r);
    pipWidth_ = int(r.sideViewSize.x);
    pipHeight_ = int(r.sideViewSize.y);
    if (r.settingsValid) valid_ = settings_;
    window_.setTitle(ui_->windowTitle());
    a_ = r.abSettings ? std::optional<Settings>(*r.abSettings) : std::nullopt;
    split_ = r.abSplit && a_;
    divider_ = r.abDivider;
    if (!split_) abStats_.reset();
    if (r.sweepCancel) sweep_->cancel();
    if (r.sweepStart) sweep_->start(*r.sweepStart, valid_, a_, presetPath_.empty() ? opt_.presetDir : folderOf(presetPath_));
    if (r.tuneCancel) tune_->cancel();
    if (r.tuneStart) tune_->start(*r.tuneStart, valid_, a_, presetPath_.empty() ? opt_.presetDir : folderOf(presetPath_));
}

// A's ground truth is read back here, while the renderer holds A's maps (the live frame comes
// next and replaces them): so the split view renders every frame, never reusing or scaling it.
// What the settings cost at the size this frame was drawn, every map redrawn (a kept map's work
// is its last redraw's), so the label does not drop to the main pass whenever the maps are kept.
void EditorSession::modelCost(FrameStats& stats) const {
    const metrics::ModelledCost m = metrics::modelFrame(costProfile_, metrics::withEveryMapRedrawn(stats));
    stats.modelMs = m.totalMs;
    stats.modelShadowMs = m.shadowMs;
    stats.costProfile = metrics::profileName(costProfile_);
}

void EditorSession::renderA(const ui::UiRequests& r, int width, int height) {
    abRendered_ = false;
    if (!split_ || swapped_) return;
    Settings live = valid_;
    live.output.width = width;
    live.output.height = height;
    const Settings a = aOnLive(*a_, live);
    if (!accuracyA_) accuracyA_ = std::make_unique<EditorAccuracy>();
    try {
        abStats_ = ab_.renderA(*renderer_, a);
        modelCost(*abStats_);
        abRendered_ = true;
    } catch (const std::exception& e) {  // A's settings on this view are rejected: say so, show live
        status_ = std::string("A: ") + e.what();
        abStats_.reset();
    }
    accuracyA_->update(glfwGetTime(), r.accuracyWanted, abRendered_, *renderer_, a, scene_);
}

SceneFrameInputs EditorSession::sceneInputs(int width, int height, bool interactive) const {
    SceneFrameInputs in;
    in.sceneKey = loadedKey_;
    in.rendererGeneration = rendererGeneration_;
    in.live = interactive ? interactiveMaps(valid_, interactive_.mapDivisor()) : valid_;
    in.live.output.width = width;
    in.live.output.height = height;
    if (swapped_) in.live.output.view = View::Side;
    if (split_ && !swapped_) {
        Settings live = valid_;
        live.output.width = width;
        live.output.height = height;
        in.a = aOnLive(*a_, live);
    }
    in.orbit = orbit_;
    in.pipWidth = pipWidth_, in.pipHeight = pipHeight_;
    in.swapped = swapped_;
    return in;
}

bool EditorSession::renderScene(const ui::UiRequests& r, bool final) {
    const bool moving = (previousValid_ && viewMoving(*previousValid_, valid_));
    previousValid_ = valid_;
    // The split renders at full size, and every frame while A's own Accuracy job is on its way
    // (renderA says why); once A's figures are in, a frame that changed nothing reuses both
    // halves (issue 21 #10: it rendered every frame, 5 fps with nothing touched).
    const bool splitShown = split_ && !swapped_;
    const bool aFiguresPending = splitShown && (!accuracyA_ || accuracyA_->busy());
    const bool scalable = !final && !splitShown;
    const bool interactive = moving && scalable;
    const double scale = interactive_.update(interactive, cpuFrameMs_);
    const int width = interactive ? scaledSize(sceneWidth_, scale) : sceneWidth_;
    const int height = interactive ? scaledSize(sceneHeight_, scale) : sceneHeight_;
    const SceneFrameInputs in = sceneInputs(width, height, interactive);
    sceneReused_ = !aFiguresPending && frameCache_.check(in).empty();
    if (sceneReused_) {
        ++reusedFrames_;
    } else {
        const auto t0 = std::chrono::steady_clock::now();
        renderA(r, width, height);
        heldRendered_ = renderViews(in.live, interactive ? scale : 1.0);
        // The GL work is queued, not done, when the calls return: finish it, so the time is the
        // scene's and not the panels' (on llvmpipe the swap would wait for it anyway).
        finishDeviceWork();
        sceneMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        sceneRenderMs_.push_back(sceneMs_);
        sceneScales_.push_back(scale);
        frameCache_.rendered(in, heldRendered_ ? &stats_ : nullptr, abRendered_ && abStats_ ? &*abStats_ : nullptr);
        heldInteractive_ = interactive;
        heldScale_ = interactive ? scale : 1.0;
        heldMapSize_ = interactive ? in.live.cascades.mapSize : 0;
        heldWidth_ = width, heldHeight_ = height;
    }
    // An interactive image is never measured or probed: the figures describe the full frame only.
    return heldRendered_ && !heldInteractive_ && heldWidth_ == sceneWidth_ && heldHeight_ == sceneHeight_;
}

// The viewport the panels leave, in framebuffer pixels (HiDPI scale) with GL's bottom-left origin.
void EditorSession::placeScene(const ui::UiRequests& r) {
    const ImGuiIO& io = ImGui::GetIO();
    int fbWidth = 0, fbHeight = 0;
    window_.framebufferSize(fbWidth, fbHeight);
    const float sx = io.DisplayFramebufferScale.x, sy = io.DisplayFramebufferScale.y;
    scenePos_ = r.scenePos;
    sceneSize_ = r.sceneSize;
    sceneX_ = std::clamp(int(std::lround(r.scenePos.x * sx)), 0, fbWidth);
    sceneWidth_ = std::clamp(int(std::lround(r.sceneSize.x * sx)), 0, fbWidth - sceneX_);
    const int top = std::clamp(int(std::lround(r.scenePos.y * sy)), 0, fbHeight);
    sceneHeight_ = std::clamp(int(std::lround(r.sceneSize.y * sy)), 0, fbHeight - top);
    sceneY_ = fbHeight - top - sceneHeight_;
}

bool EditorSession::renderViews(const Settings& s, double pipScale) {
    const int width = s.output.width, height = s.output.height;
    Settings pipSettings = s;  // the picture shows the other camera
    pipSettings.output.view = valid_.output.view;
    try {
        stats_ = renderer_->render(s, orbit_);
        modelCost(stats_);
    } catch (const std::exception& e) {  // settings the math rejects: keep the last image
        status_ = e.what();
        return false;
    }
    {
        // Until the panel reports the size it shows the picture at: a quarter of the window.
        // While the view moves the picture takes the scene's interactive scale too.
        int w = pipWidth_ >= 16 ? scaledSize(pipWidth_, pipScale) : std::max(16, width / 4);
        int h = pipHeight_ >= 16 ? scaledSize(pipHeight_, pipScale) : std::max(16, height / 4);
        if (swapped_) h = std::max(16, w * height / width);  // the main view keeps the window's aspect
        retiredPip_ = OffscreenTarget();
        if (w != pip_.width() || h != pip_.height()) retiredPip_ = std::move(pip_);
        pip_.ensure(w, h);
        if (swapped_) renderer_->renderMainView(pipSettings, pip_);
        else renderer_->renderSideView(pipSettings, orbit_, pip_);
    }
    // A moment filter's tiles read the frame's cascade block (filter kind, exponents).
    const bool moments = isMomentFilter(valid_.filter.kind);
    if (moments) renderer_->bindShadingInputs();
    shadowTiles_->update(renderer_->shadowMaps(), 256, moments ? &renderer_->momentMaps() : nullptr);
    return true;
}

// After the render, so a change made this frame (camera keys, a widget) drops the overlay before
// it would be drawn over a view it no longer describes.
void EditorSession::updateAccuracy(const ui::UiRequests& r, bool rendered, int width, int height) {
    Settings s = valid_;  // what the main camera shows, at the scene view's size
    s.output.width = width;
    s.output.height = height;
    accuracy_->update(glfwGetTime(), r.accuracyWanted, rendered, *renderer_, s, scene_);
    if (r.errorOverlay && !swapped_ && !split_ && accuracy_->overlay())
        ui::drawErrorOverlay(reinterpret_cast<ImTextureID>(std::uintptr_t(accuracy_->overlay())), scenePos_, sceneSize_);
}

// The scene into its viewport; the rest of the window is the panels' (cleared, so nothing of an
// earlier, larger viewport shows between them). With the split on, A's columns go left of the divider.
void EditorSession::present() {
    clearWindow({0.06f, 0.06f, 0.06f, 1.0f});
    // An interactive frame is smaller than the viewport: stretched over it, filtered.
    const bool full = renderer_->width() == sceneWidth_ && renderer_->height() == sceneHeight_;
    blitColor(renderer_->framebuffer(), {0, 0, renderer_->width(), renderer_->height()}, 0,
              {sceneX_, sceneY_, sceneWidth_, sceneHeight_}, full ? BlitFilter::Nearest : BlitFilter::Linear);
    if (split_ && !swapped_ && abStats_) ab_.composite(0, divider_, sceneX_, sceneY_);
}

ui::UiInputs EditorSession::uiInputs() {
    auto tex = [](GLuint id) { return reinterpret_cast<ImTextureID>(std::uintptr_t(id)); };
    ui::UiInputs in;
    in.stats = &stats_;
    in.cpuFrameMs = cpuFrameMs_;
    in.scene = {sceneMs_, heldScale_, heldMapSize_, sceneReused_};
    for (int i = 0; i < shadowTiles_->layers(); ++i) {
        in.shadowLayers.push_back(tex(shadowTiles_->layerTexture(i)));
        if (GLuint v = shadowTiles_->varianceTexture(i)) in.shadowVariance.push_back(tex(v));
    }
    for (const CascadeStats& c : stats_.cascades) in.shadowMapSizes.push_back(c.mapSize);
    if (shadowTiles_->atlasTexture()) {
        in.shadowAtlas = tex(shadowTiles_->atlasTexture());
        in.shadowAtlasWidth = renderer_->shadowMaps().layout().textures.front().width;
        in.shadowAtlasHeight = renderer_->shadowMaps().layout().textures.front().height;
    }
    in.sideView = pip_.colorTexture() ? tex(pip_.colorTexture()) : tex(0);
    in.presetFiles = presetFiles_;
    in.statusLine = status_;
    in.accuracy = accuracy_->view();
    in.checkScene = [this](const std::string& spec, bool ground, const fs::path& baseDir) {
        return checkScene(spec, ground, baseDir);
    };
    in.probe = probeView_;
    // The split planes as the side view picture shows them (not when it shows the main camera).
    if (!swapped_ && pip_.width() > 0 && pip_.height() > 0)
        in.sideSplitHandles = sideSplitHandles(renderer_->plan(), orbit_, float(pip_.width()) / float(pip_.height()));
    if (abStats_) in.ab.stats = &*abStats_;
    if (accuracyA_) in.ab.accuracy = accuracyA_->view();
    in.sweep = &sweep_->view();
    in.sweepableFields = sweepable_;
    in.tune = &tune_->view();
    in.tuneObjectives = tuneObjectives_;
    return in;
}

// The pixel the panels asked for, from the frame just rendered (the main view only).
void EditorSession::updateProbe(const ui::UiRequests& r, bool rendered) {
    probeView_ = {};
    if (!r.probeWanted || !rendered || swapped_) return;
    Settings s = valid_;
    s.output.width = sceneWidth_;
    s.output.height = sceneHeight_;
    probe_.update(true, *renderer_, s);
    std::vector<float> texelWorld;
    for (const CascadeStats& c : stats_.cascades) texelWorld.push_back(c.texelWorldSize);
    probeView_ = readProbe(*probe_.samples(), int(r.probePixel.x), int(r.probePixel.y), s, texelWorld, accuracy_->classes());
}

namespace {
// CPU time of every thread of the process (the UI, llvmpipe's rasterisers, the Accuracy rays):
// unlike wall time it barely depends on what else the machine runs, so a benchmark on a shared
// machine still says what a frame costs.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}
}  // namespace

void EditorSession::frame(const fs::path* screenshot, bool final) {
    auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = processCpuMs();
    if (opt_.hover.size() == 2) {  // scripted: the pointer rests there, as a user's would
        if (frameMs_.empty()) glfwFocusWindow(window_.handle());
        glfwSetCursorPos(window_.handle(), opt_.hover[0], opt_.hover[1]);
    }
    window_.beginFrame();
    const unsigned long events = window_.eventCount();
    bool newEvents = events != lastEvents_ || window_.inputQueued();
    lastEvents_ = events;
    if (window_.shouldClose()) {  // the close button asks the panels first (unsaved changes)
        newEvents = true;  // Ctrl+C is no GLFW event: the frames that answer it must follow
        window_.cancelClose();
        ui_->requestQuit();
    }
    handleInput();
    sweep_->poll();
    tune_->poll();
    const ui::UiRequests requests = ui_->draw(settings_, uiInputs());
    applyRequests(requests);
    if (const SceneOptions options{.ground = valid_.ground}; sceneKey(valid_.scene, sceneBase(), options) != loadedKey_)
        loadScene(valid_.scene, options);
    bool sceneRendered = false;
    if (sceneWidth_ >= 16 && sceneHeight_ >= 16) {
        const bool rendered = renderScene(requests, final);
        sceneRendered = !sceneReused_;
        updateAccuracy(requests, rendered, sceneWidth_, sceneHeight_);
        updateProbe(requests, rendered);
        present();
    }
    window_.endFrame();
    int width = 0, height = 0;
    window_.framebufferSize(width, height);
    if (screenshot) writeScreenshot(*screenshot, width, height);
    window_.swapBuffers();
    cpuFrameMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    frameMs_.push_back(cpuFrameMs_);
    frameCpuMs_.push_back(processCpuMs() - cpu0);
    noteActivity(newEvents, sceneRendered, requests);
}

std::string EditorSession::shownState() const {
    auto accuracyState = [](const EditorAccuracy& a) {
        const ui::AccuracyView v = a.view();
        return std::to_string(int(v.state)) + v.phase + std::to_string(v.seconds) + v.error;
    };
    const ui::SweepView& sweep = sweep_->view();
    return status_ + '\n' + ui_->windowTitle() + '\n' + accuracyState(*accuracy_) + '\n' +
           (accuracyA_ ? accuracyState(*accuracyA_) : "") + '\n' + std::to_string(int(sweep.state)) + ' ' +
           std::to_string(sweep.done) + ' ' + std::to_string(sweep.points.size()) + ' ' + std::to_string(sweep.errors.size()) +
           ' ' + std::to_string(int(tune_->view().state)) + ' ' + std::to_string(tune_->view().chart.points.size());
}

void EditorSession::noteActivity(bool events, bool sceneRendered, const ui::UiRequests& r) {
    std::string shown = shownState();
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
    activity_.animating = keyDown || buttonDown || opt_.orbitDegPerFrame != 0.0f;
    activity_.jobRunning = accuracy_->busy() || (split_ && accuracyA_ && accuracyA_->busy()) || sweep_->running() ||
                          tune_->running();
}

void EditorSession::writeSceneShot(const fs::path& file) const {
    writeImageAtomic(file, {renderer_->width(), renderer_->height(), renderer_->readRgba8()});
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), renderer_->width(), renderer_->height());
}

void EditorSession::saveAs(const fs::path& file) {
    Settings s = valid_;
    s.output.width = renderer_->width();
    s.output.height = renderer_->height();
    savePresetRebased(s, sceneBase(), file);  // relative scene paths follow the file (issue 13 #1)
    presetPath_ = file;
    std::printf("saved %s\n", file.string().c_str());
}

void EditorSession::writeLayoutReport(const fs::path& file) const {
    auto box = [](ImVec2 pos, ImVec2 size) { return nlohmann::json::array({pos.x, pos.y, size.x, size.y}); };
    const ImGuiIO& io = ImGui::GetIO();
    nlohmann::json j{{"display", {io.DisplaySize.x, io.DisplaySize.y}}, {"scene", box(scenePos_, sceneSize_)}};
    j["windows"] = nlohmann::json::object();
    for (const auto& [key, r] : ui_->itemRects())
        if (key.rfind("window.", 0) == 0) j["windows"][key.substr(7)] = box(r.min, {r.max.x - r.min.x, r.max.y - r.min.y});
        else j["items"][key] = box(r.min, {r.max.x - r.min.x, r.max.y - r.min.y});  // where a script clicks
    writeTextAtomic(file, j.dump(2) + "\n");
    std::printf("wrote %s\n", file.string().c_str());
}

void EditorSession::printFrameTimes() const {
    if (frameMs_.size() < 3) return;
    std::vector<double> t(frameMs_.begin() + 1, frameMs_.end());  // the first frame compiles shaders
    std::sort(t.begin(), t.end());
    double median = t[t.size() / 2];
    std::vector<double> c(frameCpuMs_.begin() + 1, frameCpuMs_.end());
    std::sort(c.begin(), c.end());
    std::printf("%zu frames, median frame %.1f ms (%.1f fps), process CPU %.1f ms a frame\n", t.size(), median,
                1000.0 / median, c[c.size() / 2]);
    // The UI's frame rate and the scene's render time differ once frames reuse the image.
    if (sceneRenderMs_.size() < 2) {
        std::printf("scene rendered %zu times, reused %d times\n", sceneRenderMs_.size(), reusedFrames_);
        return;
    }
    std::vector<double> r(sceneRenderMs_.begin() + 1, sceneRenderMs_.end());
    std::vector<double> k(sceneScales_.begin() + 1, sceneScales_.end());
    std::sort(r.begin(), r.end());
    std::sort(k.begin(), k.end());
    std::printf("scene rendered %zu times (median %.1f ms, median scale %.0f %%), reused %d times\n",
                sceneRenderMs_.size(), r[r.size() / 2], 100.0 * k[k.size() / 2], reusedFrames_);
}

void EditorSession::writeScreenshot(const fs::path& file, int width, int height) {
    Rgba8Image img{width, height, readWindowRgba8(width, height)};
    for (std::size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;  // the window is opaque
    writeImageAtomic(file, img);
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), width, height);
}

}  // namespace st::app
