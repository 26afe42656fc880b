#pragma once
// All of the editor's GL (issue 21 #1): the renderer of the model's scene, the
// picture-in-picture, the shadow-map tiles, the frame cache and the interactive scale, the A/B
// split, the Accuracy jobs (they read the renderer's frame back) and the probe. Each frame it
// renders the model's valid settings unless the image held shows them, and presents the image
// into the scene viewport; the panels get its textures and figures through fillUiInputs.
#include "app/editor/ab_split_render.h"
#include "app/editor/editor_accuracy.h"
#include "app/editor/editor_model.h"
#include "app/editor/path_preview_render.h"
#include "app/editor/scene_frame.h"
#include "app/editor/scene_probe.h"
#include "metrics/cost_model.h"
#include "renderer/render/image_texture.h"
#include "renderer/render/offscreen_target.h"
#include "renderer/render/renderer.h"
#include "renderer/render/shadow_map_view.h"

#include <imgui.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace st::app {

// What the shell tells the viewport about this frame.
struct ViewportFrame {
    double time = 0.0;             // seconds (the Accuracy schedule's clock)
    int fbWidth = 0, fbHeight = 0; // the window's framebuffer
    ImVec2 fbScale{1.0f, 1.0f};    // framebuffer pixels per display pixel (HiDPI)
    double lastFrameMs = 0.0;      // the previous frame's wall time: the interactive scale follows it
    bool final = false;            // a scripted run's last frame: full resolution whatever moves
    bool accuracyWanted = false;   // the panels' last requests: the Accuracy panel is open
    bool errorOverlay = false;     // ... with its overlay on
    bool probeWanted = false;      // ... the mouse rests over the scene at probePixel
    ImVec2 probePixel{0.0f, 0.0f};
};

// A scene render of this frame, for the frame times.
struct SceneRender {
    bool rendered = false;  // a new image (else the held one was shown again, or no viewport)
    double ms = 0.0;        // its wall time, GL work finished
    double scale = 1.0;     // its scale of the viewport
    bool reused = false;    // the held image was shown again
};

// The whole window as the back buffer holds it (panels and all), opaque.
void writeWindowShot(const std::filesystem::path& file, int width, int height);

class ViewportRenderer {
public:
    static constexpr int kTileSize = 256;  // texels per side of each shadow-map viewer tile

    explicit ViewportRenderer(const EditorModel& model);
    ~ViewportRenderer();
    ViewportRenderer(const ViewportRenderer&) = delete;
    ViewportRenderer& operator=(const ViewportRenderer&) = delete;

    // Renders the model's valid settings into the scene viewport (unless the image held shows
    // them), updates the Accuracy jobs, the overlay and the probe, and presents the image. Call
    // with the ImGui frame begun (the overlay goes on its background list).
    SceneRender frame(EditorModel& model, const ViewportFrame& f);
    // The textures and figures the panels show.
    void fillUiInputs(ui::UiInputs& in, const EditorModel& model) const;
    // The surface point under `mouse` (display pixels) in the probe's last read-back, else `fallback`.
    glm::vec3 pickedPoint(ImVec2 mouse, ImVec2 scenePos, ImVec2 fbScale, glm::vec3 fallback) const;
    const EditorAccuracy& accuracy() const { return *accuracy_; }
    bool jobRunning(const EditorModel& model) const;  // an Accuracy job whose progress shows
    std::string shownState() const;  // what changes on screen without a scene render: the jobs' states
    int imageWidth() const { return renderer_->width(); }
    int imageHeight() const { return renderer_->height(); }
    void writeSceneShot(const std::filesystem::path& file) const;  // the main view, no panels
    // The bytes its textures and buffers hold, by kind (issue 39 #10), and the process's resident set.
    ui::MemoryView memory() const;

private:
    void placeScene(const EditorModel& model, const ViewportFrame& f);
    SceneFrameInputs sceneInputs(const EditorModel& model, int width, int height, bool interactive) const;
    // false: the held image is not the frame of the valid settings at the viewport's full size.
    bool renderScene(EditorModel& model, const ViewportFrame& f, SceneRender& out);
    void renderA(const EditorModel& model, const ViewportFrame& f, int width, int height, std::string& message);
    bool renderViews(const EditorModel& model, const Settings& s, double pipScale, std::string& message);
    void updateAccuracy(const EditorModel& model, const ViewportFrame& f, bool rendered);
    void updateProbe(const EditorModel& model, const ViewportFrame& f, bool rendered);
    void present(const EditorModel& model);
    // Preview path: a chunk of its frames rendered, or the loop shown. true while a preview is
    // on: the live image, the Accuracy jobs and the probe wait (the renderer holds path frames).
    bool preview(EditorModel& model, const ViewportFrame& f, SceneRender& out);
    void drawPreview(const EditorModel& model, const ViewportFrame& f);
    void modelCost(FrameStats& stats) const;

    std::unique_ptr<Renderer> renderer_;
    int sceneGeneration_ = 0;  // the model's scene the renderer draws
    OffscreenTarget pip_;
    std::unique_ptr<ShadowMapView> shadowTiles_;
    std::unique_ptr<EditorAccuracy> accuracy_;
    std::unique_ptr<EditorAccuracy> accuracyA_;  // A's own ground-truth job
    SceneProbe probe_;
    ui::ProbeView probeView_;  // shown by the next draw()
    // The scene viewport, framebuffer pixels from the bottom left (GL's origin).
    int sceneX_ = 0, sceneY_ = 0, sceneWidth_ = 0, sceneHeight_ = 0;
    FrameStats stats_;
    // Redraw only what changed, at an interactive resolution while the view moves (issue 13 #10).
    SceneFrameCache frameCache_;
    InteractiveScale interactive_;
    std::optional<Settings> previousValid_;  // last frame's, to see the view move
    bool heldRendered_ = false;     // the held image is a frame of the held inputs (not a failure)
    bool heldInteractive_ = false;  // the held image is an interactive one (smaller, coarser maps)
    double heldScale_ = 1.0;
    int heldMapSize_ = 0;           // its cascades.mapSize while interactive
    int heldWidth_ = 0, heldHeight_ = 0;
    double sceneMs_ = 0.0;          // wall time of the held image's render
    double lastFullMs_ = 0.0;       // ... of the last full-quality one (a slow change previews first)
    bool sceneReused_ = false;      // this frame showed the held image again
    AbSplitRender ab_;
    std::optional<FrameStats> abStats_;  // A's last frame while the split is on
    bool abRendered_ = false;            // A's settings rendered on the held frame
    std::uint64_t previewGeneration_ = 0;  // the model's preview the frames belong to
    std::unique_ptr<PathPreviewRender> previewRender_;
    int previewWidth_ = 0, previewHeight_ = 0;  // the frames' size: the viewport's when it began
    double playStart_ = 0.0;
    ImageTexture previewTexture_;
    int shownFrame_ = -1;  // the frame in previewTexture_ (-2: the flicker map)
    // Models each rendered frame's cost (FrameStats::modelMs) for the A/B labels: the shipped profile.
    metrics::CostProfile costProfile_;
};

}  // namespace st::app
