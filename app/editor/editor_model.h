#pragma once
// The editor's state without a window or GL (issue 21 #1): the document and its settings, the
// last valid settings (what is rendered), A, the loaded scene, the cameras, the Sweep and Tune children and
// the messages. The shell feeds it the frame's camera input and the panels' requests; the
// viewport renders what it holds. Nothing here includes GL or GLFW (docs/layers.json's
// app/editor/model layer checks it), so its tests run without a context.
//
// Messages belong here and are cleared by the change that made them stale (issue 21 #4, #11):
// a valid settings change, a scene that loads, the render that works again.
#include "app/editor/editor_sweep.h"
#include "app/editor/editor_tune.h"
#include "app/editor/fly_camera.h"
#include "app/editor/motion_preview.h"
#include "app/editor/view_actions.h"
#include "renderer/render/side_view.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "ui/editor_ui.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

// One frame's camera input, as the shell reads it from the window. The mouse fields are zero
// while a panel has the mouse, the keys while a panel has the keyboard.
struct CameraInput {
    FlyInput fly;                   // right mouse + WASD/QE, middle mouse, wheel
    bool overScene = false;         // the mouse is over the scene, not a panel
    glm::vec2 mouseDelta{0.0f};     // this frame's movement, pixels
    float wheel = 0.0f;
    bool leftDown = false;
    bool altClick = false;          // Alt + left button pressed this frame
    glm::vec3 pivot{0.0f};          // with altClick: the surface point under the cursor (or the target)
    float scriptedOrbitDeg = 0.0f;  // --orbit-deg-per-frame: a benchmark's turn, no undo step
    double seconds = 0.0;           // the frame's time (the recorded move's pauses)
};

struct ModelOptions {
    std::optional<std::filesystem::path> preset;  // default: <presetDir>/default.json if present
    std::filesystem::path presetDir = "presets";
    std::filesystem::path executable;             // runs the Sweep panel's child (empty: /proc/self/exe)
};

class EditorModel {
public:
    // Loads the preset (a bad file given by name throws) and its scene (throws when it does not load).
    explicit EditorModel(const ModelOptions& opt);
    ~EditorModel();
    EditorModel(const EditorModel&) = delete;
    EditorModel& operator=(const EditorModel&) = delete;

    // input: the camera gestures (fly, pan, orbit, the side camera) on the edited settings.
    void applyCamera(const CameraInput& in);
    void poll();  // the Sweep child's progress; never blocks
    // The panels, drawn over the edited settings (between ImGui::NewFrame and Render).
    ui::UiRequests drawPanels(const ui::UiInputs& in) { return ui_->draw(settings_, in); }
    // What the panels asked for: the valid settings follow a valid edit, an invalid one keeps
    // them and says why; A, the split, the swapped views, the Sweep; a new scene is loaded.
    void apply(const ui::UiRequests& r);
    // A message from the renderer (settings the math rejects); "" when the frame rendered.
    void setRenderMessage(std::string message);
    // Loads a scene the panels are about to choose: "" when it loads (it is kept for apply).
    std::string checkScene(const std::string& spec, bool ground, const std::filesystem::path& baseDir);
    void requestQuit() { ui_->requestQuit(); }

    const Settings& settings() const { return settings_; }  // what the panels edit
    Settings& edit() { return settings_; }  // ... as a panel would (tests); apply() sees the result
    const Settings& valid() const { return valid_; }        // the last settings that passed validation
    const std::optional<Settings>& a() const { return a_; }
    bool splitShown() const { return split_ && a_ && !swapped_; }  // the A/B split is on screen
    float divider() const { return divider_; }
    bool swapped() const { return swapped_; }  // side view full window, main camera in the corner
    const OrbitCamera& sideCamera() const { return orbit_; }
    int pipWidth() const { return pipWidth_; }
    int pipHeight() const { return pipHeight_; }
    ImVec2 scenePos() const { return scenePos_; }    // the scene viewport, ImGui display pixels
    ImVec2 sceneSize() const { return sceneSize_; }
    bool quitRequested() const { return quit_; }
    // The messages on screen, joined: the renderer's, the scene's, the settings' and the actions'.
    std::string message() const;
    // What changes on screen without a scene render (the frame pacer compares it): the messages,
    // the window title, the Sweep and Tune children's progress.
    std::string shownState() const;
    const std::shared_ptr<const Scene>& scene() const { return scene_; }
    const std::string& sceneKey() const { return loadedKey_; }
    int sceneGeneration() const { return sceneGeneration_; }  // a new Scene: the renderer is rebuilt
    std::filesystem::path sceneBase() const;  // what relative scene paths are relative to
    const std::filesystem::path& presetPath() const { return presetPath_; }
    const std::vector<std::filesystem::path>& presetFiles() const { return presetFiles_; }
    const std::vector<std::string>& sweepableFields() const { return sweepable_; }
    const EditorSweep& sweep() const { return *sweep_; }
    const EditorTune& tune() const { return *tune_; }
    // `tune --objective` choices (name, label) for the Tune panel.
    const std::vector<std::pair<std::string, std::string>>& tuneObjectives() const { return tuneObjectives_; }
    ui::EditorUi& ui() { return *ui_; }
    const ui::EditorUi& ui() const { return *ui_; }
    bool orbiting() const { return orbiting_; }
    // View > Full quality while moving: no interactive scale or smaller maps while the view moves.
    bool fullQualityWhileMoving() const { return fullQualityWhileMoving_; }
    MotionPreview& preview() { return preview_; }
    const MotionPreview& preview() const { return preview_; }
    const CameraPathRecorder& recordedMove() const { return recorded_; }
    void startPreview();  // View > Preview path
    ui::MotionView motionView() const { return {fullQualityWhileMoving_, preview_.active(), preview_.overlay()}; }
    void savePresetAs(const std::filesystem::path& file, int width, int height);  // the valid settings

private:
    void loadScene(const std::string& spec, const SceneOptions& options);
    void scanPresets();

    ModelOptions opt_;
    std::filesystem::path presetPath_;
    Settings settings_;
    Settings valid_;
    std::optional<Settings> a_;  // "Set as A", as the panels hold it
    bool split_ = false;
    float divider_ = 0.5f;
    bool swapped_ = false;
    bool quit_ = false;
    // The loaded scene; prepared_ is one checkScene loaded that the settings do not name yet.
    std::shared_ptr<const Scene> scene_;  // shared with the Accuracy jobs
    std::string loadedScene_, loadedKey_;
    SceneOptions loadedOptions_;
    std::shared_ptr<const Scene> prepared_;
    std::string preparedKey_;
    int sceneGeneration_ = 0;
    std::unique_ptr<ui::EditorUi> ui_;  // the document, its history and the panels' own state
    FlyState fly_;
    CameraGesture cameraGesture_;
    bool orbiting_ = false;       // an Alt + left drag of the main camera is going on
    glm::vec3 orbitPivot_{0.0f};  // ... around this point
    OrbitCamera orbit_;           // the side camera
    int pipWidth_ = 0, pipHeight_ = 0;
    ImVec2 scenePos_{0.0f, 0.0f}, sceneSize_{0.0f, 0.0f};
    // Each message lives until the change that makes it stale.
    std::string renderMessage_;    // the last render failed: until one works
    std::string sceneMessage_;     // the scene did not load: until one does
    std::string settingsMessage_;  // the edited settings are invalid: until a valid change
    std::string actionMessage_;    // Frame scene's note: until the next settings change
    std::vector<std::filesystem::path> presetFiles_;
    bool fullQualityWhileMoving_ = false;
    MotionPreview preview_;
    CameraPathRecorder recorded_;  // the user's last camera move, for Preview path
    std::string previewMessage_;   // why a preview did not start: until the next request
    void applyMotion(const ui::MotionRequests& m, bool changed);
    std::unique_ptr<EditorSweep> sweep_;
    std::vector<std::string> sweepable_;  // sweep::isSweepable over the field table
    std::unique_ptr<EditorTune> tune_;    // the Tune panel's child
    std::vector<std::pair<std::string, std::string>> tuneObjectives_ = app::tuneObjectives();
};

}  // namespace st::app
