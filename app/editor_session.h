#pragma once
// One editing session: the Settings being tuned, the loaded scene and its renderer, the views
// (main camera, side camera picture-in-picture, shadow-map tiles) and the panels.
#include "metrics/cost_model.h"
#include "app/ab_split_render.h"
#include "app/editor_accuracy.h"
#include "app/editor_app.h"
#include "app/editor_sweep.h"
#include "app/editor_tune.h"
#include "app/editor_window.h"
#include "app/fly_camera.h"
#include "app/frame_pacer.h"
#include "app/view_actions.h"
#include "app/scene_probe.h"
#include "app/scene_frame.h"
#include "renderer/render/offscreen_target.h"
#include "renderer/render/renderer.h"
#include "renderer/render/shadow_map_view.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "ui/editor_ui.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

class EditorSession {
public:
    EditorSession(EditorWindow& window, const EditorOptions& opt);
    ~EditorSession();
    // One frame: input, render, panels, present. Writes a screenshot of the whole window first
    // if `screenshot` is set. `final`: a scripted run's last frame, at full resolution whatever
    // moves (its image is what --scene-screenshot and --save-as take).
    void frame(const std::filesystem::path* screenshot, bool final = false);
    bool quitRequested() const { return quit_; }
    void writeSceneShot(const std::filesystem::path& file) const;  // the main view, no panels
    void saveAs(const std::filesystem::path& file);  // output size = the scene view's size
    void printFrameTimes() const;                    // medians of the frame and of the scene renders
    // {"display": [w, h], "scene": [x, y, w, h], "windows": {"Settings": [x, y, w, h], ...}}, ImGui's
    // display pixels from the top left, as the last frame placed them.
    void writeLayoutReport(const std::filesystem::path& file) const;
    const EditorAccuracy& accuracy() const { return *accuracy_; }
    // What the last frame saw, for the FramePacer: events, changes, animation, jobs.
    const FrameActivity& activity() const { return activity_; }
    int framesDrawn() const { return int(frameMs_.size()); }
    const CameraSettings& camera() const { return settings_.camera; }
    bool splitShown() const { return split_ && !swapped_; }  // the A/B split is on screen
    int exitCode() const { return exitCode_; }

private:
    void loadScene(const std::string& spec, const SceneOptions& options);
    std::string checkScene(const std::string& spec, bool ground, const std::filesystem::path& baseDir);
    std::filesystem::path sceneBase() const;  // what relative scene paths are relative to
    void handleInput();
    glm::vec3 pickedPoint(ImVec2 mouse) const;
    void placeScene(const ui::UiRequests& r);
    void applyRequests(const ui::UiRequests& r);
    // s: sized and viewed; pipScale: of the picture-in-picture's size. false: the settings
    // failed, the last image stays.
    bool renderViews(const Settings& s, double pipScale);
    void renderA(const ui::UiRequests& r, int width, int height);  // the split's A half, before the live frame
    SceneFrameInputs sceneInputs(int width, int height, bool interactive) const;
    // Renders the scene views unless the image held already shows this frame; false: the image
    // held is not the frame of the current settings at the viewport's full size.
    bool renderScene(const ui::UiRequests& r, bool final);
    void updateAccuracy(const ui::UiRequests& r, bool rendered, int width, int height);
    void present();
    void updateProbe(const ui::UiRequests& r, bool rendered);
    ui::UiInputs uiInputs();
    void scanPresets();
    void writeScreenshot(const std::filesystem::path& file, int width, int height);
    // The last frame's activity (FramePacer): `events`, whether the scene image was rendered.
    void noteActivity(bool events, bool sceneRendered, const ui::UiRequests& r);
    std::string shownState() const;  // what changes on screen without a scene render: messages, jobs

    EditorWindow& window_;
    EditorOptions opt_;
    std::filesystem::path presetPath_;
    Settings settings_;   // what the panels edit
    Settings valid_;      // the last settings that passed validation: what is rendered
    std::string loadedScene_;
    std::string loadedKey_;                  // sceneKey() of the scene loaded
    std::shared_ptr<const Scene> prepared_;  // loaded by checkScene, not shown yet
    std::string preparedKey_;
    SceneOptions loadedOptions_;
    std::shared_ptr<const Scene> scene_;  // shared with the Accuracy panel's background job
    std::unique_ptr<Renderer> renderer_;
    OffscreenTarget pip_;
    OffscreenTarget retiredPip_;  // the previous picture after a resize: this frame's panels may name it
    std::unique_ptr<ShadowMapView> shadowTiles_;
    std::unique_ptr<ui::EditorUi> ui_;
    std::unique_ptr<EditorAccuracy> accuracy_;
    SceneProbe probe_;
    ui::ProbeView probeView_;  // shown by the next draw()
    std::vector<std::filesystem::path> presetFiles_;
    int pipWidth_ = 0, pipHeight_ = 0;  // the size the panels show the picture-in-picture at
    // The scene viewport the panels leave, framebuffer pixels from the bottom left (GL's origin).
    int sceneX_ = 0, sceneY_ = 0, sceneWidth_ = 0, sceneHeight_ = 0;
    ImVec2 scenePos_{0.0f, 0.0f}, sceneSize_{0.0f, 0.0f};  // the same in ImGui's display pixels
    FrameStats stats_;
    FlyState fly_;
    CameraGesture cameraGesture_;
    OrbitCamera orbit_;
    bool orbiting_ = false;             // an Alt + left drag of the main camera is going on
    glm::vec3 orbitPivot_{0.0f};        // ... around this point
    bool swapped_ = false;   // side view full window, main camera in the corner
    bool quit_ = false;
    int exitCode_ = 0;
    std::string status_;
    double lastTime_ = 0.0;
    double cpuFrameMs_ = 0.0;
    std::vector<double> frameMs_;  // wall time of every frame, for printFrameTimes
    std::vector<double> frameCpuMs_;  // CPU time of the whole process in every frame
    // Redraw only what changed, at an interactive resolution while the view moves (issue 13 #10).
    SceneFrameCache frameCache_;
    InteractiveScale interactive_;
    int rendererGeneration_ = 0;
    std::optional<Settings> previousValid_;  // last frame's, to see the view move
    bool heldRendered_ = false;   // the held image is a frame of the held inputs (not a failure)
    bool heldInteractive_ = false;  // the held image is an interactive one (smaller, coarser maps)
    double heldScale_ = 1.0;      // the held image's scale of the viewport
    int heldMapSize_ = 0;         // its cascades.mapSize while interactive
    int heldWidth_ = 0, heldHeight_ = 0;  // and its pixels
    double sceneMs_ = 0.0;        // wall time of the held image's render, GL work finished
    bool sceneReused_ = false;    // this frame showed the held image again
    std::vector<double> sceneRenderMs_;  // of every frame that rendered, for printFrameTimes
    std::vector<double> sceneScales_;    // of every frame that rendered
    int reusedFrames_ = 0;
    // A/B split (Compare menu) and the Sweep panel's runs.
    std::optional<Settings> a_;    // "Set as A", as the panels hold it
    bool split_ = false;
    float divider_ = 0.5f;
    AbSplitRender ab_;
    // Models each rendered frame's cost (FrameStats::modelMs) for the A/B labels: the shipped profile.
    metrics::CostProfile costProfile_;
    void modelCost(FrameStats& stats) const;
    std::optional<FrameStats> abStats_;          // A's last frame while the split is on
    bool abRendered_ = false;                    // A's settings rendered on the held frame
    std::unique_ptr<EditorAccuracy> accuracyA_;  // A's own ground-truth job
    std::unique_ptr<EditorSweep> sweep_;
    std::unique_ptr<EditorTune> tune_;
    std::vector<std::pair<std::string, std::string>> tuneObjectives_ = tuneObjectives();
    std::vector<std::string> sweepable_;         // sweep::isSweepable over the field table
    FrameActivity activity_;
    unsigned long lastEvents_ = 0;  // EditorWindow::eventCount() at the previous frame
    std::string lastShown_;         // shownState() at the previous frame
};

}  // namespace st::app
