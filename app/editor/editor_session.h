#pragma once
// The editor's shell (issue 21 #1): the window, its input and the ImGui frame around the model
// (app/editor/editor_model.h: settings, document, messages, no GL) and the viewport
// (app/editor/viewport_renderer.h: all of the editor's GL). One frame reads input, updates the
// model, renders, draws the panels and applies their requests to the model.
#include "app/editor/editor_app.h"
#include "app/editor/editor_model.h"
#include "app/editor/editor_window.h"
#include "app/editor/frame_pacer.h"
#include "app/editor/frame_times.h"
#include "app/editor/viewport_renderer.h"

#include <filesystem>
#include <memory>
#include <string>

namespace st::app {

class EditorSession {
public:
    EditorSession(EditorWindow& window, const EditorOptions& opt);
    ~EditorSession();
    // One frame. Writes a screenshot of the whole window first if `screenshot` is set. `final`:
    // a scripted run's last frame, at full resolution whatever moves (its image is what
    // --scene-screenshot and --save-as take).
    void frame(const std::filesystem::path* screenshot, bool final = false);
    bool quitRequested() const { return model_->quitRequested(); }
    void writeSceneShot(const std::filesystem::path& file) const { viewport_->writeSceneShot(file); }
    void saveAs(const std::filesystem::path& file);  // output size = the scene view's size
    void printFrameTimes() const { times_.print(); }
    // {"display": [w, h], "scene": [x, y, w, h], "windows": {"Settings": [x, y, w, h], ...}}, ImGui's
    // display pixels from the top left, as the last frame placed them.
    void writeLayoutReport(const std::filesystem::path& file) const;
    const EditorAccuracy& accuracy() const { return viewport_->accuracy(); }
    // What the last frame saw, for the FramePacer: events, changes, animation, jobs.
    const FrameActivity& activity() const { return activity_; }
    int framesDrawn() const { return times_.frames(); }
    const FrameTimes& frameTimes() const { return times_; }
    const CameraSettings& camera() const { return model_->settings().camera; }
    std::string message() const { return model_->message(); }  // the status lines the panels show
    bool splitShown() const { return model_->splitShown(); }
    bool swapped() const { return model_->swapped(); }  // Tab: the side view fills the scene viewport
    ui::MemoryView memory() const { return viewport_->memory(); }
    // --preview-path: the preview has not started yet (it starts on the second frame) or still renders.
    bool previewPending() const {
        return opt_.previewPath && (times_.frames() < 2 || model_->preview().state() == MotionPreview::State::Rendering);
    }
    std::string previewLine() const { return model_->preview().line(); }

private:
    CameraInput cameraInput() const;
    ViewportFrame viewportFrame(bool final) const;
    void fillUiInputs(ui::UiInputs& in) const;
    // The last frame's activity (FramePacer): `events`, whether the scene image was rendered.
    void noteActivity(bool events, bool sceneRendered, const ui::UiRequests& r);

    EditorWindow& window_;
    EditorOptions opt_;
    std::unique_ptr<EditorModel> model_;
    std::unique_ptr<ViewportRenderer> viewport_;
    ViewportFrame asked_;  // what the panels' last requests ask of the viewport
    FrameTimes times_;
    double lastFrameMs_ = 0.0;
    FrameActivity activity_;
    unsigned long lastEvents_ = 0;  // EditorWindow::eventCount() at the previous frame
    std::string lastShown_;         // what the previous frame showed besides the scene
};

}  // namespace st::app
