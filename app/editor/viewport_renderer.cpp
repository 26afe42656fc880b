#include "app/editor/viewport_renderer.h"

#include "metrics/map_warnings.h"

#include "app/cost_profile_file.h"
#include "app/editor/memory_breakdown.h"
#include "app/editor/side_split_handles.h"
#include "renderer/image/image_io.h"
#include "renderer/render/device.h"
#include "renderer/render/present.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace st::app {

ViewportRenderer::ViewportRenderer(const EditorModel& model)
    : renderer_(std::make_unique<Renderer>(*model.scene())),
      sceneGeneration_(model.sceneGeneration()),
      shadowTiles_(std::make_unique<ShadowMapView>()),
      accuracy_(std::make_unique<EditorAccuracy>()),
      costProfile_(loadCostProfileOption("")) {}

ViewportRenderer::~ViewportRenderer() = default;

SceneRender ViewportRenderer::frame(EditorModel& model, const ViewportFrame& f) {
    if (model.sceneGeneration() != sceneGeneration_) {
        renderer_.reset();  // the old renderer refers to the old scene
        renderer_ = std::make_unique<Renderer>(*model.scene());
        sceneGeneration_ = model.sceneGeneration();
    }
    placeScene(model, f);
    SceneRender out;
    if (sceneWidth_ < 16 || sceneHeight_ < 16) return out;
    if (preview(model, f, out)) return out;
    const bool rendered = renderScene(model, f, out);
    updateAccuracy(model, f, rendered);
    updateProbe(model, f, rendered);
    present(model);
    return out;
}

// The viewport the panels leave, in framebuffer pixels (HiDPI scale) with GL's bottom-left origin.
void ViewportRenderer::placeScene(const EditorModel& model, const ViewportFrame& f) {
    const ImVec2 pos = model.scenePos(), size = model.sceneSize();
    sceneX_ = std::clamp(int(std::lround(pos.x * f.fbScale.x)), 0, f.fbWidth);
    sceneWidth_ = std::clamp(int(std::lround(size.x * f.fbScale.x)), 0, f.fbWidth - sceneX_);
    const int top = std::clamp(int(std::lround(pos.y * f.fbScale.y)), 0, f.fbHeight);
    sceneHeight_ = std::clamp(int(std::lround(size.y * f.fbScale.y)), 0, f.fbHeight - top);
    sceneY_ = f.fbHeight - top - sceneHeight_;
}

// What the settings cost at the size this frame was drawn, every map redrawn (a kept map's work
// is its last redraw's), so the label does not drop to the main pass whenever the maps are kept.
void ViewportRenderer::modelCost(FrameStats& stats) const {
    const metrics::ModelledCost m = metrics::modelFrame(costProfile_, metrics::withEveryMapRedrawn(stats));
    stats.modelMs = m.totalMs;
    stats.modelShadowMs = m.shadowMs;
    stats.costProfile = metrics::profileName(costProfile_);
}

// A's ground truth is read back here, while the renderer holds A's maps (the live frame comes
// next and replaces them).
void ViewportRenderer::renderA(const EditorModel& model, const ViewportFrame& f, int width, int height,
                               std::string& message) {
    abRendered_ = false;
    if (!model.splitShown()) return;
    Settings live = model.valid();
    live.output.width = width;
    live.output.height = height;
    const Settings a = aOnLive(*model.a(), live);
    if (!accuracyA_) accuracyA_ = std::make_unique<EditorAccuracy>();
    try {
        abStats_ = ab_.renderA(*renderer_, a);
        modelCost(*abStats_);
        abRendered_ = true;
    } catch (const std::exception& e) {  // A's settings on this view are rejected: say so, show live
        message = std::string("A: ") + e.what();
        abStats_.reset();
    }
    accuracyA_->update(f.time, f.accuracyWanted, abRendered_, *renderer_, a, model.scene());
}

SceneFrameInputs ViewportRenderer::sceneInputs(const EditorModel& model, int width, int height, bool interactive) const {
    SceneFrameInputs in;
    in.sceneKey = model.sceneKey();
    in.rendererGeneration = sceneGeneration_;
    in.live = interactive ? interactiveMaps(model.valid(), interactive_.mapDivisor()) : model.valid();
    in.live.output.width = width;
    in.live.output.height = height;
    if (model.swapped()) in.live.output.view = View::Side;
    if (model.splitShown()) {
        Settings live = model.valid();
        live.output.width = width;
        live.output.height = height;
        in.a = aOnLive(*model.a(), live);
    }
    in.orbit = model.sideCamera();
    in.pipWidth = model.pipWidth(), in.pipHeight = model.pipHeight();
    in.swapped = model.swapped();
    return in;
}

bool ViewportRenderer::renderScene(EditorModel& model, const ViewportFrame& f, SceneRender& out) {
    const bool moving = previousValid_ && viewMoving(*previousValid_, model.valid());
    const bool changed = previousValid_ && !(*previousValid_ == model.valid());
    previousValid_ = model.valid();
    if (!model.splitShown()) abStats_.reset();
    // The split renders at full size, and every frame while A's own Accuracy job is on its way
    // (renderA says why); once A's figures are in, a frame that changed nothing reuses both
    // halves (issue 21 #10: it rendered every frame, 5 fps with nothing touched).
    const bool splitShown = model.splitShown();
    const bool aFiguresPending = splitShown && (!accuracyA_ || accuracyA_->busy());
    const bool scalable = !f.final && !splitShown;
    // A settings change whose last full frame took long (cascades 4 -> 3 froze the window for 3 s
    // with the old picture, issue 39 #7) is shown first as the interactive preview, at once; the
    // full frame follows on the next, still frame, and the status line says so.
    constexpr double kSlowChangeMs = 250.0;
    const bool slowChange = changed && !moving && lastFullMs_ > kSlowChangeMs;
    const bool interactive = (moving || slowChange) && scalable && !model.fullQualityWhileMoving();
    const double scale = interactive_.update(interactive, f.lastFrameMs);
    const int width = interactive ? scaledSize(sceneWidth_, scale) : sceneWidth_;
    const int height = interactive ? scaledSize(sceneHeight_, scale) : sceneHeight_;
    const SceneFrameInputs in = sceneInputs(model, width, height, interactive);
    sceneReused_ = !aFiguresPending && frameCache_.check(in).empty();
    out.reused = sceneReused_;
    if (!sceneReused_) {
        const auto t0 = std::chrono::steady_clock::now();
        std::string message;
        renderA(model, f, width, height, message);
        // An interactive frame's smaller maps go into the renderer's second set: the full-size
        // maps stay for the full frame after the move (it re-allocated them, issue 39 #1).
        RenderOptions options = renderer_->options();
        options.previewMaps = interactive;
        renderer_->setOptions(options);
        heldRendered_ = renderViews(model, in.live, interactive ? scale : 1.0, message);
        options.previewMaps = false;
        renderer_->setOptions(options);
        // Casters the light box cuts off lose their shadows: said where the artist looks, as
        // `render` prints it (issue 39 #6), not only as the figures panel's orange "!".
        if (heldRendered_)
            for (const std::string& w : metrics::zExtensionWarnings(stats_))
                message += (message.empty() ? "" : "\n") + std::string("warning: ") + w;
        model.setRenderMessage(message);
        // The GL work is queued, not done, when the calls return: finish it, so the time is the
        // scene's and not the panels' (on llvmpipe the swap would wait for it anyway).
        finishDeviceWork();
        sceneMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (!interactive) lastFullMs_ = sceneMs_;
        if (interactive && slowChange) {
            char note[128];
            std::snprintf(note, sizeof note, "preview: the full frame follows (about %.0f ms)", lastFullMs_);
            model.setRenderMessage(message + (message.empty() ? "" : "\n") + note);
        }
        out = {true, sceneMs_, scale};
        frameCache_.rendered(in, heldRendered_ ? &stats_ : nullptr, abRendered_ && abStats_ ? &*abStats_ : nullptr);
        heldInteractive_ = interactive;
        heldScale_ = interactive ? scale : 1.0;
        heldMapSize_ = interactive ? in.live.cascades.mapSize : 0;
        heldWidth_ = width, heldHeight_ = height;
    }
    // An interactive image is never measured or probed: the figures describe the full frame only.
    return heldRendered_ && !heldInteractive_ && heldWidth_ == sceneWidth_ && heldHeight_ == sceneHeight_;
}

bool ViewportRenderer::renderViews(const EditorModel& model, const Settings& s, double pipScale, std::string& message) {
    const int width = s.output.width, height = s.output.height;
    Settings pipSettings = s;  // the picture shows the other camera
    pipSettings.output.view = model.valid().output.view;
    try {
        stats_ = renderer_->render(s, model.sideCamera());
        modelCost(stats_);
    } catch (const std::exception& e) {  // settings the math rejects: keep the last image
        message += (message.empty() ? "" : "\n") + std::string(e.what());
        return false;
    }
    // Until the panel reports the size it shows the picture at: a quarter of the window.
    // While the view moves the picture takes the scene's interactive scale too.
    const int pipW = model.pipWidth(), pipH = model.pipHeight();
    const int w = pipW >= 16 ? scaledSize(pipW, pipScale) : std::max(16, width / 4);
    int h = pipH >= 16 ? scaledSize(pipH, pipScale) : std::max(16, height / 4);
    if (model.swapped()) h = std::max(16, w * height / width);  // the main view keeps the window's aspect
    pip_.ensure(w, h);
    if (model.swapped()) renderer_->renderMainView(pipSettings, pip_);
    else renderer_->renderSideView(pipSettings, model.sideCamera(), pip_);
    // A moment filter's tiles read the frame's cascade block (filter kind, exponents).
    const bool moments = isMomentFilter(model.valid().filter.kind);
    if (moments) renderer_->bindShadingInputs();
    shadowTiles_->update(renderer_->shadowMaps(), kTileSize, moments ? &renderer_->momentMaps() : nullptr);
    return true;
}

// After the render, so a change made (camera keys, a widget) drops the overlay before it would
// be drawn over a view it no longer describes.
void ViewportRenderer::updateAccuracy(const EditorModel& model, const ViewportFrame& f, bool rendered) {
    Settings s = model.valid();  // what the main camera shows, at the scene view's size
    s.output.width = sceneWidth_;
    s.output.height = sceneHeight_;
    accuracy_->update(f.time, f.accuracyWanted, rendered, *renderer_, s, model.scene());
    // Over the shaded view only: the debug views (cascades, density, side) have colours of their own
    // that the overlay's red and blue would be read as (issue 39 #3).
    const bool shaded = model.valid().output.view == View::Shaded;
    if (f.errorOverlay && shaded && !model.swapped() && !model.splitShown() && accuracy_->overlay())
        ui::drawErrorOverlay(reinterpret_cast<ImTextureID>(std::uintptr_t(accuracy_->overlay())), model.scenePos(),
                             model.sceneSize());
}

// The pixel the panels asked for, from the frame just rendered (the main view only).
void ViewportRenderer::updateProbe(const EditorModel& model, const ViewportFrame& f, bool rendered) {
    probeView_ = {};
    if (!f.probeWanted || !rendered || model.swapped()) return;
    Settings s = model.valid();
    s.output.width = sceneWidth_;
    s.output.height = sceneHeight_;
    probe_.update(true, *renderer_, s, &accuracy_->measurePass());
    std::vector<float> texelWorld;
    for (const CascadeStats& c : stats_.cascades) texelWorld.push_back(c.texelWorldSize);
    std::vector<float> depthRange;
    for (const csm::CascadeFit& c : renderer_->plan().cascades) depthRange.push_back(c.lsBox.max.z - c.lsBox.min.z);
    probeView_ = readProbe(*probe_.samples(), int(f.probePixel.x), int(f.probePixel.y), s, texelWorld, accuracy_->classes(),
                           depthRange);
}

// The scene into its viewport; the rest of the window is the panels' (cleared, so nothing of an
// earlier, larger viewport shows between them). With the split on, A's columns go left of the divider.
void ViewportRenderer::present(const EditorModel& model) {
    clearWindow({0.06f, 0.06f, 0.06f, 1.0f});
    // An interactive frame is smaller than the viewport: stretched over it, filtered.
    const bool full = renderer_->width() == sceneWidth_ && renderer_->height() == sceneHeight_;
    blitColor(renderer_->framebuffer(), {0, 0, renderer_->width(), renderer_->height()}, 0,
              {sceneX_, sceneY_, sceneWidth_, sceneHeight_}, full ? BlitFilter::Nearest : BlitFilter::Linear);
    if (model.splitShown() && abStats_) ab_.composite(0, model.divider(), sceneX_, sceneY_);
}

bool ViewportRenderer::preview(EditorModel& model, const ViewportFrame& f, SceneRender& out) {
    MotionPreview& p = model.preview();
    if (p.generation() != previewGeneration_) {  // started, or stopped: the renderer held path frames
        previewGeneration_ = p.generation();
        previewRender_.reset();
        shownFrame_ = -1;
        frameCache_.invalidate();
        previousValid_.reset();
    }
    if (!p.active()) return false;
    if (!previewRender_) {
        previewRender_ = std::make_unique<PathPreviewRender>();
        previewWidth_ = sceneWidth_, previewHeight_ = sceneHeight_;
    }
    Settings path = p.path();
    path.output.width = previewWidth_;
    path.output.height = previewHeight_;
    if (p.state() == MotionPreview::State::Rendering) {
        // A chunk of frames a frame, so the panels stay responsive and show the progress.
        const auto t0 = std::chrono::steady_clock::now();
        const auto elapsedMs = [&] { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); };
        try {
            do {
                previewRender_->renderNext(*renderer_, path);
                p.frameRendered();
            } while (p.state() == MotionPreview::State::Rendering && elapsedMs() < 150.0);
        } catch (const std::exception& e) {  // settings the math rejects on some path frame
            model.setRenderMessage(std::string("Preview path: ") + e.what());
            p.stop();
            return false;
        }
        finishDeviceWork();
        if (p.state() == MotionPreview::State::Playing) {
            p.flickerMeasured(previewRender_->flicker()->flipRate);
            playStart_ = f.time;
        }
        out = {true, elapsedMs(), 1.0};
    } else {
        out.reused = true;
    }
    present(model);  // while rendering: the frame just rendered
    if (p.state() == MotionPreview::State::Playing) drawPreview(model, f);
    return true;
}

// The loop's frame of this moment, or the flicker map, over the scene viewport.
void ViewportRenderer::drawPreview(const EditorModel& model, const ViewportFrame& f) {
    const MotionPreview& p = model.preview();
    const int frame = p.overlay() ? -2 : p.frameAt(f.time - playStart_);
    if (frame != shownFrame_) {
        const Rgba8Image& img = frame == -2 ? previewRender_->flickerMap() : previewRender_->frames()[std::size_t(frame)];
        previewTexture_.upload(img.width, img.height, img.pixels);
        shownFrame_ = frame;
    }
    const ImVec2 pos = model.scenePos(), size = model.sceneSize();
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(std::uintptr_t(previewTexture_.id())), pos,
                                             {pos.x + size.x, pos.y + size.y});
}

void ViewportRenderer::fillUiInputs(ui::UiInputs& in, const EditorModel& model) const {
    auto tex = [](GLuint id) { return reinterpret_cast<ImTextureID>(std::uintptr_t(id)); };
    in.stats = &stats_;
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
    in.sideViewSwapped = model.swapped();
    in.accuracy = accuracy_->view();
    in.probe = probeView_;
    // The split planes as the side view picture shows them (not when it shows the main camera).
    if (!model.swapped() && pip_.width() > 0 && pip_.height() > 0)
        in.sideSplitHandles = sideSplitHandles(renderer_->plan(), model.sideCamera(), float(pip_.width()) / float(pip_.height()));
    if (abStats_) in.ab.stats = &*abStats_;
    if (accuracyA_) in.ab.accuracy = accuracyA_->view();
    in.memory = memory();
}

namespace {
MeasureHeld measureHeld(std::string what, const MeasurePass& pass, std::size_t samplesPixels) {
    const MeasurePass::Held h = pass.held();
    return {std::move(what), h.keptPixels, h.readBackPixels, {h.surfaceWidth, h.surfaceHeight},
            {h.shadowWidth, h.shadowHeight}, samplesPixels};
}
}  // namespace

ui::MemoryView ViewportRenderer::memory() const {
    MemoryInputs in;
    in.scene = {renderer_->width(), renderer_->height()};
    in.pip = {pip_.width(), pip_.height()};
    in.abImage = {ab_.image().width(), ab_.image().height()};
    in.maps = renderer_->shadowMaps().held(MapSet::Full);
    in.previewMaps = renderer_->shadowMaps().held(MapSet::Preview);
    in.momentBytes = renderer_->momentMaps().layers() > 0 ? renderer_->momentMaps().bytes() : 0;
    in.screenShadowBytes = renderer_->screenShadow() ? renderer_->screenShadow()->bytes() : 0;
    in.screenShadowBytes += accuracy_->measurePass().held().screenShadowBytes;
    in.tileSize = shadowTiles_->layers() > 0 ? kTileSize : 0;
    in.tiles = shadowTiles_->layers();
    for (int i = 0; i < shadowTiles_->layers(); ++i) in.tiles += shadowTiles_->varianceTexture(i) ? 1 : 0;
    in.atlas = {shadowTiles_->atlasWidth(), shadowTiles_->atlasHeight()};
    const MeasureSamples* probed = probe_.samples();
    in.measures.push_back(measureHeld("Accuracy and probe", accuracy_->measurePass(), probed ? probed->size() : 0));
    if (accuracyA_) in.measures.push_back(measureHeld("A's accuracy", accuracyA_->measurePass(), 0));
    in.overlay = {accuracy_->overlayWidth(), accuracy_->overlayHeight()};
    const Scene& scene = renderer_->sceneGpu().scene();
    in.vertices = scene.vertices.size();
    in.indices = scene.indices.size();
    in.clusteredIndices = renderer_->sceneGpu().clustered().indices.size();
    for (const Image& image : scene.images) in.images.push_back({image.width, image.height});
    return {memoryBreakdown(in), residentBytes()};
}

glm::vec3 ViewportRenderer::pickedPoint(ImVec2 mouse, ImVec2 scenePos, ImVec2 fbScale, glm::vec3 fallback) const {
    const MeasureSamples* m = probe_.samples();
    const int x = int(std::floor((mouse.x - scenePos.x) * fbScale.x));
    const int y = int(std::floor((mouse.y - scenePos.y) * fbScale.y));
    if (!m || x < 0 || y < 0 || x >= m->width || y >= m->height) return fallback;
    const std::size_t i = std::size_t(y) * std::size_t(m->width) + std::size_t(x);
    return m->covered(i) ? glm::vec3(m->position[i]) : fallback;
}

bool ViewportRenderer::jobRunning(const EditorModel& model) const {
    return accuracy_->busy() || (model.splitShown() && accuracyA_ && accuracyA_->busy());
}

std::string ViewportRenderer::shownState() const {
    auto accuracyState = [](const EditorAccuracy& a) {
        const ui::AccuracyView v = a.view();
        return std::to_string(int(v.state)) + v.phase + std::to_string(v.seconds) + v.error;
    };
    return accuracyState(*accuracy_) + '\n' + (accuracyA_ ? accuracyState(*accuracyA_) : "");
}

void writeWindowShot(const std::filesystem::path& file, int width, int height) {
    Rgba8Image img{width, height, readWindowRgba8(width, height)};
    for (std::size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;  // the window is opaque
    writeImageAtomic(file, img);
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), width, height);
}

void ViewportRenderer::writeSceneShot(const std::filesystem::path& file) const {
    writeImageAtomic(file, {renderer_->width(), renderer_->height(), renderer_->readRgba8()});
    std::printf("wrote %s (%dx%d)\n", file.string().c_str(), renderer_->width(), renderer_->height());
}

}  // namespace st::app
