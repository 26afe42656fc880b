#include "app/editor/editor_model.h"

#include "app/editor/preset_list.h"
#include "app/scene_preset.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_spec.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace st::app {
namespace fs = std::filesystem;

EditorModel::EditorModel(const ModelOptions& opt) : opt_(opt) {
    presetPath_ = opt.preset ? *opt.preset : opt.presetDir / "default.json";
    if (opt.preset && isGltfPath(*opt.preset)) {
        // A scene of the user's own: a new preset for it (app/scene_preset.h), not saved yet.
        settings_ = presetForScene(*opt.preset, {});
        presetPath_.clear();
    } else if (opt.preset || fs::exists(presetPath_)) {
        settings_ = loadPreset(presetPath_);  // a bad file given by name fails
    } else {
        presetPath_.clear();
    }
    valid_ = settings_;
    loadScene(settings_.scene, {.ground = settings_.ground});
    ui_ = std::make_unique<ui::EditorUi>(opt.presetDir);
    ui_->setDocument(settings_, presetPath_);
    std::error_code ec;
    const fs::path exe = opt.executable.empty() ? fs::read_symlink("/proc/self/exe", ec) : opt.executable;
    sweep_ = std::make_unique<EditorSweep>(exe);  // this binary's `sweep`
    tune_ = std::make_unique<EditorTune>(exe);    // ... and its `tune`
    for (const FieldInfo& field : fieldTable())
        if (sweep::isSweepable(field)) sweepable_.emplace_back(field.path);
    scanPresets();
}

EditorModel::~EditorModel() = default;

void EditorModel::scanPresets() { presetFiles_ = listPresetFiles(opt_.presetDir); }

fs::path EditorModel::sceneBase() const { return presetPath_.empty() ? opt_.presetDir : folderOf(presetPath_); }

void EditorModel::loadScene(const std::string& spec, const SceneOptions& options) {
    try {
        const std::string key = st::sceneKey(spec, sceneBase(), options);
        auto scene = key == preparedKey_ ? prepared_ : std::make_shared<const Scene>(st::loadScene(spec, sceneBase(), options));
        prepared_.reset(), preparedKey_.clear();
        scene_ = std::move(scene);
        ++sceneGeneration_;
        loadedScene_ = spec;
        loadedKey_ = key;
        loadedOptions_ = options;
        sceneMessage_.clear();
    } catch (const std::exception& e) {
        sceneMessage_ = e.what();
        if (!scene_) throw;  // nothing loaded yet: the session cannot start
        valid_.scene = loadedScene_;  // keep rendering the scene that works; the panel shows why
        valid_.ground = loadedOptions_.ground;
    }
}

// Loads the scene the panels are about to choose, so a file that does not load is refused before
// it reaches the document (issue 13 #1); the scene loaded is kept for loadScene.
std::string EditorModel::checkScene(const std::string& spec, bool ground, const fs::path& baseDir) {
    const SceneOptions options{.ground = ground};
    const std::string key = st::sceneKey(spec, baseDir, options);
    if (key == loadedKey_ || key == preparedKey_) return {};
    try {
        prepared_ = std::make_shared<const Scene>(st::loadScene(spec, baseDir, options));
        preparedKey_ = key;
        return {};
    } catch (const std::exception& e) {
        return e.what();
    }
}

void EditorModel::applyCamera(const CameraInput& in) {
    const CameraSettings before = settings_.camera;
    // Alt + left drag orbits the main camera around the point under the cursor where it began.
    if (!swapped_ && in.overScene && in.altClick) {
        orbiting_ = true;
        orbitPivot_ = in.pivot;
    }
    if (swapped_ && in.overScene) {  // full-window side camera: left mouse orbits, wheel zooms
        if (in.leftDown) orbit_.yawDeg -= in.mouseDelta.x * 0.3f, orbit_.pitchDeg += in.mouseDelta.y * 0.3f;
        orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, in.wheel), 0.05f, 20.0f);
    } else if (orbiting_) {
        orbitCamera(settings_.camera, orbitPivot_, in.mouseDelta);
        // Ended after its movement is taken: the mouse queue may put the last moves and the
        // release in one frame, and that frame's movement belongs to the drag.
        if (!in.leftDown) orbiting_ = false;
    } else if (in.fly.look || in.fly.pan || in.fly.wheel != 0.0f) {
        // Only then: re-deriving the target from the position each frame drifts by rounding,
        // and every drift would be an undo step.
        updateFlyCamera(settings_.camera, fly_, in.fly, scene_->wsBounds);
    }
    // A fly, pan or orbit gesture is one undo step (issue 13 #4).
    if (auto start = cameraGesture_.update(before, settings_.camera, in.fly.look || in.fly.pan || orbiting_)) {
        Settings atStart = settings_;
        atStart.camera = *start;
        ui_->recordEdit(atStart, settings_);
    }
    if (in.scriptedOrbitDeg != 0.0f) {  // a benchmark's camera path: no gesture, no undo step
        const float a = glm::radians(in.scriptedOrbitDeg), c = std::cos(a), sn = std::sin(a);
        const glm::vec3 d = settings_.camera.position - settings_.camera.target;
        settings_.camera.position = settings_.camera.target + glm::vec3(c * d.x + sn * d.z, d.y, -sn * d.x + c * d.z);
    }
    recorded_.frame(settings_.camera, in.seconds, in.fly.look || in.fly.pan || orbiting_);
    if (settings_.camera != before) preview_.stop();  // the view moved: the loop shows another
    // The camera moves in this frame's image: the render comes before the panels' requests.
    // A camera the math rejects (or other settings it rejects) waits for apply() as any edit does.
    if (settings_.camera != before) {
        Settings moved = valid_;
        moved.camera = settings_.camera;
        if (validate(moved).empty()) valid_ = std::move(moved);
    }
}

void EditorModel::poll() {
    sweep_->poll();
    tune_->poll();
}

void EditorModel::apply(const ui::UiRequests& r) {
    if (r.quit) quit_ = true;
    if (r.change != ChangeClass::None) actionMessage_.clear();
    if (r.frameScene) {  // moves the camera only, as one undo step; near/far are tuning settings
        const Settings before = settings_;
        std::vector<csm::Aabb> items;
        for (const DrawItem& d : scene_->draws) items.push_back(d.wsBounds);
        actionMessage_ = frameKeepingClipPlanes(settings_.camera, framingBounds(items, scene_->wsBounds));
        ui_->recordEdit(before, settings_);
    }
    if (r.swapSideView) swapped_ = !swapped_;
    if (r.presetsChanged) scanPresets();
    presetPath_ = ui_->presetFile();  // a load or a save may have moved the document
    orbit_.yawDeg -= r.sideViewOrbit.x * 0.3f;
    orbit_.pitchDeg = std::clamp(orbit_.pitchDeg + r.sideViewOrbit.y * 0.3f, -89.0f, 89.0f);
    orbit_.zoom = std::clamp(orbit_.zoom * std::pow(0.9f, r.sideViewZoom), 0.05f, 20.0f);
    scenePos_ = r.scenePos;
    sceneSize_ = r.sceneSize;
    pipWidth_ = int(r.sideViewSize.x);
    pipHeight_ = int(r.sideViewSize.y);
    if (r.settingsValid) {
        valid_ = settings_;
        settingsMessage_.clear();
    } else if (const std::vector<std::string> issues = validate(settings_); !issues.empty()) {
        // The image keeps the last valid settings (issue 21 #4): say so where messages go, too.
        settingsMessage_ = "not applied, the image shows the last valid settings: " + issues.front();
        if (issues.size() > 1) settingsMessage_ += " (and " + std::to_string(issues.size() - 1) + " more)";
    }
    a_ = r.abSettings ? std::optional<Settings>(*r.abSettings) : std::nullopt;
    split_ = r.abSplit && a_;
    divider_ = r.abDivider;
    applyMotion(r.motion, r.change != ChangeClass::None || r.frameScene || r.swapSideView);
    if (r.sweepCancel) sweep_->cancel();
    if (r.sweepStart) sweep_->start(*r.sweepStart, valid_, a_, sceneBase());
    if (r.tuneCancel) tune_->cancel();
    if (r.tuneStart) tune_->start(*r.tuneStart, valid_, a_, sceneBase());
    if (const SceneOptions options{.ground = valid_.ground}; st::sceneKey(valid_.scene, sceneBase(), options) != loadedKey_)
        loadScene(valid_.scene, options);
}

// View > Motion. A change to the settings or the view stops a preview: its frames show others.
void EditorModel::applyMotion(const ui::MotionRequests& m, bool changed) {
    if (changed) previewMessage_.clear();
    if (m.toggleFullQuality) fullQualityWhileMoving_ = !fullQualityWhileMoving_;
    if (m.previewStop || (changed && preview_.active())) preview_.stop();
    if (m.toggleFlickerOverlay) preview_.toggleOverlay();
    if (m.previewStart) startPreview();
}

void EditorModel::startPreview() {
    previewMessage_.clear();
    std::string source;
    if (std::optional<Settings> path = previewPath(valid_, recorded_.poses(), source)) preview_.start(std::move(*path), source);
    else previewMessage_ = "Preview path: the preset has no camera path and the camera has not moved yet";
}

void EditorModel::setRenderMessage(std::string message) { renderMessage_ = std::move(message); }

std::string EditorModel::message() const {
    std::string all;
    const std::string preview = preview_.line();
    for (const std::string* m : {&renderMessage_, &sceneMessage_, &settingsMessage_, &actionMessage_, &previewMessage_, &preview})
        if (!m->empty()) all += (all.empty() ? "" : "\n") + *m;
    return all;
}

std::string EditorModel::shownState() const {
    const ui::SweepView& sweep = sweep_->view();
    const ui::TuneView& tune = tune_->view();
    return message() + '\n' + ui_->windowTitle() + '\n' + std::to_string(int(sweep.state)) + ' ' +
           std::to_string(sweep.done) + ' ' + std::to_string(sweep.points.size()) + ' ' + std::to_string(sweep.errors.size()) +
           ' ' + std::to_string(int(tune.state)) + ' ' + std::to_string(tune.chart.points.size());
}

void EditorModel::savePresetAs(const fs::path& file, int width, int height) {
    Settings s = valid_;
    s.output.width = width;
    s.output.height = height;
    // Relative scene paths follow the file (issue 13 #1), and so does the "$schema" of the preset
    // open, as File > Save as keeps it (ui::saveDocument, issue 21 #8): one write.
    std::string schema = presetPath_.empty() ? "" : presetSchemaRef(presetPath_);
    if (schema.empty()) schema = defaultSchemaRef(sceneBase() / "untitled.json", opt_.presetDir);  // relative to sceneBase()
    savePresetRebased(s, sceneBase(), file, schema);
    presetPath_ = file;
}

}  // namespace st::app
