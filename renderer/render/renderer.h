#pragma once
// Draws one frame of a Settings value: a depth pass per cascade into its map (ShadowMaps), then the
// main pass into an offscreen colour target. Knows nothing about windows: headless replay reads
// the pixels back, the editor blits or shows the texture.
#include "renderer/csm/cascade_plan.h"
#include "renderer/gpu/gl.h"
#include "renderer/render/shader_library.h"
#include "renderer/gpu/pass_state.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/cascade_cache.h"
#include "renderer/render/draw_batches.h"
#include "renderer/render/depth_bounds_pass.h"
#include "renderer/render/frame_stats.h"
#include "renderer/render/gpu_timer.h"
#include "renderer/render/line_pass.h"
#include "renderer/render/moment_maps.h"
#include "renderer/render/offscreen_target.h"
#include "renderer/render/pass_counters.h"
#include "renderer/render/scene_gpu.h"
#include "renderer/render/screen_shadow.h"
#include "renderer/render/shadow_maps.h"
#include "renderer/render/side_view.h"
#include "renderer/render/texel_cloud.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "shaders/interface.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace st {

// The shadow pass's culling for cascades.casterFaces (caster_pass.cpp): the face culled on
// single-sided materials (GL_NONE for both) and how draws apply it.
GLenum casterCullFace(CasterFaces faces);
FaceCulling casterCulling(CasterFaces faces);

struct RenderOptions {
    // The renderer before issue 11, kept as the benchmarks' baseline: one draw per scene item,
    // culled against each light box per item, no main-pass culling, every map every frame.
    bool naive = false;
    // Keep a cascade's map while its matrix, casters and map settings stay (cascade_cache.h).
    // Off: every map every frame (what `measure`'s cost frames time).
    bool cacheMaps = true;
    // Count FrameStats' lowerBoundTriangles (per triangle, on the CPU, when a map is redrawn).
    bool lowerBound = true;
    // Off: the main pass draws its coverage only (shaders/main_coverage.frag: the alpha test, no
    // shadow filtering or lighting). The counted work (FrameStats::work) stays the same, the image
    // does not: for a caller that reads its figures from the measurement pass (a tune's
    // evaluation), it saves a filtered shading of every fragment.
    bool shadeMain = true;
    // The frame is the editor's interactive preview (smaller maps while the view moves): its maps
    // go into a set of their own (MapSet::Preview), so the full-size ones survive for the full
    // frame that follows. Off everywhere else: one set, as before.
    bool previewMaps = false;
    // > 0: every vertex snaps to 1/subpixelSteps of a pixel (of a texel in the shadow maps) before
    // it is drawn, as a rasterizer with log2(steps) sub-pixel bits does; 0: this GPU's own grid.
    // engine-check's model draws with the grid of the GPU the engine ran on (SwiftShader: 16).
    int subpixelSteps = 0;
};

// The view block of a pass drawing through `viewProj` into a width x height viewport.
gpu_if::ViewBlock viewBlockOf(const glm::mat4& viewProj, int width, int height, int subpixelSteps);

class Renderer {
public:
    // Needs a current GL 4.5 core context; the scene must outlive the renderer.
    explicit Renderer(const Scene& scene);

    // Renders into the offscreen target, sized from s.output. View::Side shows the scene from
    // `orbit` with the cascades' wireframes instead of the main camera's image. Throws
    // std::invalid_argument for settings the cascade math rejects.
    FrameStats render(const Settings& s, const OrbitCamera& orbit = {});

    // After render(): the same frame seen from the side camera, into `out` (its own size).
    void renderSideView(const Settings& s, const OrbitCamera& orbit, OffscreenTarget& out);
    // After render(): the main camera's image into `out` (give it the same aspect ratio).
    void renderMainView(const Settings& s, OffscreenTarget& out);

    std::vector<std::uint8_t> readRgba8() const { return target_.readRgba8(); }
    GLuint colorTexture() const { return target_.colorTexture(); }
    GLuint framebuffer() const { return target_.framebuffer(); }
    GLuint shadowMapTexture(int cascade = 0) const { return shadowMaps_.texture(cascade); }
    GLuint depthTexture() const { return target_.depthTexture(); }  // main pass depth, D32F
    // Of the last render(); a cascade whose map an update interval kept holds the fit that map
    // was drawn with (its vsNear, vsFar are this frame's). With cascades.matricesOneFrameLate the
    // shading passes sample through the previous render()'s viewProj instead (not shown here).
    const csm::CascadePlan& plan() const { return plan_; }
    void setOptions(const RenderOptions& o) { options_ = o; }
    const RenderOptions& options() const { return options_; }
    void invalidateMaps() { cache_.invalidate(); }  // the next frame redraws every map
    // Binds the frame and cascade blocks of the last render() (ST_BLOCK_FRAME, ST_BLOCK_CASCADES)
    // and the shadow maps, for a pass that shades with them (the measurement pass).
    void bindShadingInputs() const;
    const SceneGpu& sceneGpu() const { return scene_; }
    const ShadowMaps& shadowMaps() const { return shadowMaps_; }
    // The moment maps of the last render() with a moment filter; layers() is 0 before one.
    const MomentMaps& momentMaps() const { return moments_; }
    // The screen-space path of the last render() or renderMainView() with filter.screenSpace on;
    // null before one.
    const ScreenShadow* screenShadow() const { return screen_.get(); }
    int width() const { return target_.width(); }
    int height() const { return target_.height(); }

private:
    void shadowPass(const Settings& s, FrameStats& stats);
    // Cascade i of the clustered path (caster_pass.cpp): culls, then redraws or keeps the map.
    // `state` is the pass state ShadowMaps::beginCascade applies with cascade i's tile.
    // Both add the renderer's own counts of a redrawn map to `work` (draws, texels, bytes).
    void cascadeCasters(const Settings& s, int i, const gpu::PassState& state, CascadeStats& cs, PassWork& work);
    void naiveCascadeCasters(const Settings& s, int i, const gpu::PassState& state, CascadeStats& cs, PassWork& work);
    // SDSM: the main camera's depth drawn into the target (a prepass of this frame, or the kept
    // one: keptPrepass_) and reduced. Counts the prepass and the reduction in their own slots.
    csm::SampleBounds reduceSamples(const Settings& s, float aspect, FrameStats& stats);
    // The reductions of the target's depth (the seen range, the cascades' sample bounds).
    csm::SampleBounds reduce(const Settings& s, const glm::mat4& proj, const csm::CameraParams& cam);
    void recordDepthBounds(const Settings& s, const csm::SampleBounds* samples, FrameStats& stats) const;
    void auditZExtension(const Settings& s, FrameStats& stats) const;
    // Draws the shaded scene seen through viewProj into `target`; shadows always follow the
    // main camera's cascades. `screen`: read the factor from screen_'s mask, built for this
    // viewProj and target size. `prepassed`: the target's depth already holds this view's depth
    // (the depth-bounds prepass), so the pass tests against it, writes none and shades each
    // pixel once: a forward renderer's z-prepass.
    void mainPass(const Settings& s, const glm::mat4& viewProj, const OffscreenTarget& target, bool screen = false,
                  bool prepassed = false);
    // filter.screenSpace: the mask of the main camera seen through viewProj at width x height.
    void buildScreenShadow(const Settings& s, const glm::mat4& viewProj, int width, int height);
    // The scene's triangles inside viewProj's frustum, with per-material face culling; with
    // `depth`, each batch with its depth-only program (the prepass).
    void drawVisible(const glm::mat4& viewProj, const DepthPrograms* depth = nullptr);
    void sidePass(const Settings& s, const OrbitCamera& orbit, const OffscreenTarget& target);
    // The counted work of the last render(): pipeline statistics of each slot plus the renderer's
    // own counts (pass_work.h).
    // keptMain: the main pass was not drawn; its work is keptMain_'s.
    void countWork(const Settings& s, bool reduce, bool moments, bool screen, FrameStats& stats, bool keptMain);
    SceneGpu scene_;
    SharedProgram depthProgram_;        // alpha-masked materials: alpha-tested
    SharedProgram depthOpaqueProgram_;  // the others: an empty fragment shader (DepthPrograms)
    DepthPrograms depthPrograms() const { return {depthOpaqueProgram_->id(), depthProgram_->id()}; }
    SharedProgram mainProgram_;
    SharedProgram coverageProgram_;  // RenderOptions::shadeMain off
    ShadowMaps shadowMaps_;
    MomentMaps moments_;
    std::unique_ptr<ScreenShadow> screen_;  // on first use
    GpuTimers timers_;
    PassCounters counters_;  // slots as the timers' (CounterSlots in renderer.cpp)
    LinePass lines_;
    OffscreenTarget target_;
    csm::CascadePlan plan_;
    std::vector<csm::CascadeFit> previousFits_;  // the last render()'s, for cascades.matricesOneFrameLate
    std::unique_ptr<DepthBoundsPass> depthBounds_;  // on first use
    gpu::UniformBuffer<gpu_if::FrameBlock> frameBlock_;
    gpu::UniformBuffer<gpu_if::CascadeBlock> cascadeBlock_;
    gpu::UniformBuffer<gpu_if::ViewBlock> viewBlock_;
    RenderOptions options_;
    CascadeCache cache_;
    DrawBatches batches_;
    std::vector<CascadeStats> held_;  // figures of each map as last drawn
    std::size_t mainTriangles_ = 0;
    int mainDraws_ = 0;
    std::uint64_t visibleCommands_ = 0;  // draw commands of the last drawVisible (multi-draw ranges)
    std::vector<PassWork> ownWork_;      // the renderer's own counts of this frame, by counter slot
    int mainRanges_ = 0;
    // RenderOptions::shadeMain off: the unshaded main pass's counted work and draw figures, kept
    // while its camera and size stay. Nobody looks at its image, and its work does not depend on
    // any shadow setting (the filter's taps are added from the settings), so the candidates of a
    // tune's view draw it once.
    struct KeptMain {
        glm::mat4 viewProj{1.0f};
        int width = 0, height = 0;
        bool prepassed = false;  // drawn over the depth prepass: it shaded fewer fragments
        PassWork work;
        std::size_t triangles = 0;
        int draws = 0, ranges = 0;
    };
    std::optional<KeptMain> keptMain_;
    // sidePass under way: mainPass clears to a dark slate, not the sky, so every cascade's
    // wireframe tint (cascade 2's blue vanished against the sky) and the white frustum read.
    bool sideBackground_ = false;
    // RenderOptions::shadeMain off: the depth prepass, kept like the main pass while its camera
    // and size stay and no pass writes the target's depth (a main pass without the prepass, a
    // side view). A tune's candidates of one view differ in shadow settings only, and the
    // prepass depends on none: it was most of the render time of a view whose maps were kept.
    struct KeptPrepass {
        glm::mat4 viewProj{1.0f};
        int width = 0, height = 0;
        PassWork work;               // its draw's counted work (the counter slot's)
        std::uint64_t commands = 0;  // its draw commands (visibleCommands_)
        bool counted = false;        // work read back (countWork of the frame that drew it)
    };
    std::optional<KeptPrepass> keptPrepass_;
    bool reusesMain(const glm::mat4& viewProj, bool screen, bool prepassed) const;
};

}  // namespace st
