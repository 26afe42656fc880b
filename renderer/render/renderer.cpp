#include "renderer/render/renderer.h"

#include "renderer/csm/culling.h"
#include "renderer/csm/filter_taps.h"
#include "renderer/csm/z_extension_audit.h"
#include "renderer/render/shader_blocks.h"
#include "renderer/render/shader_library.h"

#include <chrono>
#include <string>

namespace st {

gpu_if::ViewBlock viewBlockOf(const glm::mat4& viewProj, int width, int height, int subpixelSteps) {
    gpu_if::ViewBlock v;
    v.viewProj = viewProj;
    v.subpixelSteps = subpixelSteps;
    v.viewportWidth = width;
    v.viewportHeight = height;
    return v;
}

namespace {
// Counter slots of a frame: the timers' (cascades, main, depth bounds, moment maps) with the
// screen-space path split into its mask pass (a scene draw that filters the maps) and its blurs.
struct CounterSlots {
    int count;  // cascades
    int main() const { return count; }
    int bounds() const { return count + 1; }
    int moments() const { return count + 2; }
    int mask() const { return count + 3; }
    int screenBlur() const { return count + 4; }
    int prepass() const { return count + 5; }  // the depth prepass's draw (bounds: its reductions)
    int total() const { return count + 6; }
};

std::uint64_t pixels(int width, int height) { return std::uint64_t(width) * std::uint64_t(height); }

// What a pass's fragments read through the filter: taps per fragment from the settings.
void addFilterReads(PassWork& w, const csm::FilterTaps& t) {
    w.filterTaps += w.fragments * std::uint64_t(t.taps);
    w.bytesRead += w.fragments * std::uint64_t(t.texels) * std::uint64_t(t.bytesPerTexel);
}

// cascades.matricesOneFrameLate (three.js #30053): the maps just drawn, sampled through the light
// matrices of the frame before, when there is one with as many cascades of the same sizes.
csm::CascadePlan sampledPlan(const Settings& s, const csm::CascadePlan& plan, const std::vector<csm::CascadeFit>& previous) {
    csm::CascadePlan sampled = plan;
    if (!s.cascades.matricesOneFrameLate || previous.size() != plan.cascades.size()) return sampled;
    for (std::size_t i = 0; i < previous.size(); ++i)
        if (previous[i].mapSize != plan.cascades[i].mapSize) return plan;
    for (std::size_t i = 0; i < previous.size(); ++i) sampled.cascades[i].viewProj = previous[i].viewProj;
    return sampled;
}
}  // namespace

Renderer::Renderer(const Scene& scene) : scene_(scene) {
    depthProgram_ = sharedShaderProgram("shadow_depth.vert", "shadow_depth.frag", "shadow_depth");
    depthOpaqueProgram_ = sharedShaderProgram("shadow_depth.vert", "depth_only.frag", "depth only");
    mainProgram_ = sharedShaderProgram("main.vert", "main.frag", "main");
    coverageProgram_ = sharedShaderProgram("main.vert", "main_coverage.frag", "main coverage");
}

FrameStats Renderer::render(const Settings& s, const OrbitCamera& orbit) {
    auto t0 = std::chrono::steady_clock::now();
    FrameStats stats;
    stats.width = s.output.width;
    stats.height = s.output.height;
    stats.sceneTriangles = scene_.scene().triangleCount();
    float aspect = float(s.output.width) / float(s.output.height);
    target_.ensure(s.output.width, s.output.height);
    // Timers: cascades 0..count-1, the main pass, the depth prepass and reduction, the moment
    // maps, the screen-space path.
    const int boundsTimer = s.cascades.count + 1;
    const int filterTimer = s.cascades.count + 2;
    const int screenTimer = s.cascades.count + 3;
    timers_.beginFrame(s.cascades.count + 4);
    const CounterSlots slots{s.cascades.count};
    counters_.beginFrame(slots.total());
    ownWork_.assign(std::size_t(slots.total()), PassWork{});
    csm::SampleBounds samples;
    const bool reduce = csm::needsSampleBounds(s.cascades);
    if (reduce) {
        timers_.begin(boundsTimer);
        samples = reduceSamples(s, aspect, stats);
        timers_.end(boundsTimer);
    } else {
        keptPrepass_.reset();  // the main pass below writes the target's depth
    }
    plan_ = csm::planCascades(s, aspect, scene_.scene().wsBounds, reduce ? &samples : nullptr);
    stats.splits = plan_.splits;
    recordDepthBounds(s, reduce ? &samples : nullptr, stats);
    shadowMaps_.ensure(plan_.storage, options_.previewMaps ? MapSet::Preview : MapSet::Full);
    stats.shadowMapBytes = shadowMaps_.bytes();
    frameBlock_.upload(frameBlock(s, plan_));
    shadowPass(s, stats);
    // After: a kept map brings the fit it was drawn with.
    cascadeBlock_.upload(cascadeBlock(s, sampledPlan(s, plan_, previousFits_)));
    previousFits_ = plan_.cascades;
    auditZExtension(s, stats);
    const bool moments = isMomentFilter(s.filter.kind);
    if (moments) {
        // Made from the maps just drawn, with the filter's figures of the cascade block.
        timers_.begin(filterTimer);
        counters_.begin(slots.moments());
        cascadeBlock_.bind(ST_BLOCK_CASCADES);
        moments_.build(shadowMaps_, s);
        counters_.end(slots.moments());
        timers_.end(filterTimer);
        ownWork_[std::size_t(slots.moments())] = moments_.buildWork(s.filter.blurRadius);
        stats.filterMapBytes = moments_.bytes();
    }
    // The side camera's image filters the maps itself: the mask is the main camera's screen.
    const bool screen = screenShadowOn(s.filter) && s.output.view != View::Side;
    if (screen) {
        timers_.begin(screenTimer);
        buildScreenShadow(s, plan_.csProj * plan_.vsView, target_.width(), target_.height());
        timers_.end(screenTimer);
        stats.screenShadowBytes = screen_->bytes();
        stats.filterMapBytes += stats.screenShadowBytes;
    }
    const glm::mat4 mainViewProj = plan_.csProj * plan_.vsView;
    const bool keptMain = s.output.view != View::Side && reusesMain(mainViewProj, screen, reduce);
    if (s.output.view == View::Side) {
        sidePass(s, orbit, target_);
        keptPrepass_.reset();
    }
    else if (!keptMain)
        mainPass(s, mainViewProj, target_, screen, reduce);
    if (keptMain) {
        timers_.begin(s.cascades.count);  // nothing drawn: a valid 0 ms for the main pass's timer
        timers_.end(s.cascades.count);
        mainTriangles_ = keptMain_->triangles, mainDraws_ = keptMain_->draws, mainRanges_ = keptMain_->ranges;
    } else if (options_.shadeMain || s.output.view == View::Side) {
        keptMain_.reset();  // the target now holds another image than the kept pass's
    }
    stats.mainKept = keptMain;
    stats.mainTriangles = mainTriangles_;
    stats.mainDraws = mainDraws_;
    stats.mainRanges = mainRanges_;
    stats.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    for (int i = 0; i < s.cascades.count; ++i) {
        stats.cascades[i].gpuMs = timers_.milliseconds(i);
        stats.gpuShadowMs += stats.cascades[i].gpuMs;
    }
    stats.gpuMainMs = timers_.milliseconds(s.cascades.count);
    if (reduce) stats.gpuDepthBoundsMs = timers_.milliseconds(boundsTimer);
    if (moments) stats.gpuFilterMs = timers_.milliseconds(filterTimer);
    if (screen) {
        stats.gpuScreenShadowMs = timers_.milliseconds(screenTimer);
        stats.gpuScreenBlurMs = screen_->blurMs();
        stats.gpuFilterMs += stats.gpuScreenShadowMs;
    }
    countWork(s, reduce, moments, screen, stats, keptMain);
    if (!options_.shadeMain && s.output.view != View::Side && !screen && !keptMain) {
        PassWork counted = counters_.read(slots.main());
        counted += ownWork_[std::size_t(slots.main())];
        keptMain_ = KeptMain{mainViewProj, target_.width(), target_.height(), reduce, counted, mainTriangles_, mainDraws_,
                             mainRanges_};
    }
    return stats;
}

bool Renderer::reusesMain(const glm::mat4& viewProj, bool screen, bool prepassed) const {
    return !options_.shadeMain && !screen && keptMain_ && keptMain_->viewProj == viewProj &&
           keptMain_->prepassed == prepassed &&
           keptMain_->width == target_.width() && keptMain_->height == target_.height();
}

void Renderer::countWork(const Settings& s, bool reduce, bool moments, bool screen, FrameStats& stats, bool keptMain) {
    const CounterSlots slots{s.cascades.count};
    auto slotWork = [&](int slot) {
        PassWork w = counters_.read(slot);
        w += ownWork_[std::size_t(slot)];
        return w;
    };
    FrameWork& fw = stats.work;
    if (held_.size() < std::size_t(s.cascades.count)) held_.resize(std::size_t(s.cascades.count));  // the naive path keeps none
    for (int i = 0; i < s.cascades.count; ++i) {
        // A kept map did no work this frame, whatever the (empty) queries say.
        CascadeStats& c = stats.cascades[std::size_t(i)];
        fw.cascades.push_back(c.redrawn ? slotWork(i) : PassWork{});
        fw.shadow += fw.cascades.back();
        if (c.redrawn) held_[std::size_t(i)].drawnWork = fw.cascades.back();
        c.drawnWork = held_[std::size_t(i)].drawnWork;
    }
    const csm::FilterTaps taps = csm::filterTapsPerFragment(s.filter, s.bias.receiverPlane);
    fw.main = keptMain ? keptMain_->work : slotWork(slots.main());
    // With the screen-space path the main pass reads one R32F factor per fragment instead.
    addFilterReads(fw.main, screen ? csm::FilterTaps{1, 1, 4} : taps);
    if (reduce) {
        fw.depthBounds = slotWork(slots.bounds());
        if (!stats.prepassKept) {
            const PassWork drawn = counters_.read(slots.prepass());
            if (keptPrepass_) keptPrepass_->work = drawn, keptPrepass_->counted = true;
            fw.depthBounds += drawn;
        } else {
            fw.depthBounds += keptPrepass_->work;
        }
    }
    if (moments) fw.filter += slotWork(slots.moments());
    if (screen) {
        PassWork mask = slotWork(slots.mask());
        addFilterReads(mask, taps);
        fw.filter += mask;
        fw.filter += slotWork(slots.screenBlur());
    }
}

csm::SampleBounds Renderer::reduceSamples(const Settings& s, float aspect, FrameStats& stats) {
    gpu::DebugGroup group("depth prepass");
    const CounterSlots slots{s.cascades.count};
    const csm::CameraParams cam = csm::cameraFromSettings(s.camera, aspect);
    const glm::mat4 proj = csm::projectionMatrix(cam);
    const glm::mat4 viewProj = proj * csm::viewMatrix(cam);
    stats.prepassKept = !options_.shadeMain && keptPrepass_ && keptPrepass_->counted && keptPrepass_->viewProj == viewProj &&
                        keptPrepass_->width == target_.width() && keptPrepass_->height == target_.height();
    if (!stats.prepassKept) {
        counters_.begin(slots.prepass());
        gpu::PassState state = gpu::opaqueScenePass(target_.framebuffer(), target_.width(), target_.height());
        state.colorWrite = false;
        gpu::applyPassState(state);
        glClear(GL_DEPTH_BUFFER_BIT);
        glUseProgram(depthProgram_->id());
        viewBlock_.upload(viewBlockOf(viewProj, target_.width(), target_.height(), options_.subpixelSteps));
        viewBlock_.bind(ST_BLOCK_VIEW);
        const DepthPrograms programs = depthPrograms();
        drawVisible(viewProj, &programs);  // culled and batched, as the main pass will draw it
        counters_.end(slots.prepass());
        keptPrepass_.reset();
        if (!options_.shadeMain) keptPrepass_ = KeptPrepass{viewProj, target_.width(), target_.height(), {}, visibleCommands_};
    }
    counters_.begin(slots.bounds());
    const csm::SampleBounds out = reduce(s, proj, cam);
    counters_.end(slots.bounds());
    return out;
}

csm::SampleBounds Renderer::reduce(const Settings& s, const glm::mat4& proj, const csm::CameraParams& cam) {
    if (!depthBounds_) depthBounds_ = std::make_unique<DepthBoundsPass>();
    // Cleared and drawn into, then read by each reduction (D32F).
    PassWork& own = ownWork_[std::size_t(CounterSlots{s.cascades.count}.bounds())];
    const std::uint64_t texels = pixels(target_.width(), target_.height());
    own.draws = keptPrepass_ ? keptPrepass_->commands : visibleCommands_;
    own.texelsCleared = texels;
    own.bytesRead = 4 * texels;
    const GLuint depth = target_.depthTexture();
    if (s.cascades.fit != FitMode::Samples) return {depthBounds_->depthRange(depth, target_.width(), target_.height(), proj)};
    // Splits that follow the seen range need it first (a second reduction); others take it along.
    std::optional<csm::DepthRange> seen;
    if (csm::splitsFollowSeenDepth(s.cascades)) {
        seen = depthBounds_->depthRange(depth, target_.width(), target_.height(), proj);
        own.bytesRead += 4 * texels;
    }
    const glm::mat4 lsView = csm::lightViewMatrix(csm::lightDirection(s.light.azimuth, s.light.elevation));
    return depthBounds_->cascadeBounds(depth, target_.width(), target_.height(), proj, lsView * csm::inverseViewMatrix(cam),
                                       csm::planSplits(s, seen));
}

void Renderer::recordDepthBounds(const Settings& s, const csm::SampleBounds* samples, FrameStats& stats) const {
    stats.splitBegin = plan_.splitRange.begin;
    stats.splitEnd = plan_.splitRange.end;
    DepthBoundsStats& d = stats.depthBounds;
    d.mode = s.cascades.depthBounds == DepthBounds::Fit ? "fit" : "off";
    if (!samples) return;
    d.reduced = true;
    d.source = "depth prepass, same frame";
    if (samples->depth) {
        d.seen = true;
        d.vsMin = samples->depth->vsMin;
        d.vsMax = samples->depth->vsMax;
    }
}

void Renderer::auditZExtension(const Settings& s, FrameStats& stats) const {
    std::vector<csm::Aabb> casters;
    for (const DrawItem& item : scene_.scene().draws) casters.push_back(item.wsBounds);
    for (int i = 0; i < s.cascades.count; ++i) {
        const csm::CascadeFit& fit = plan_.cascades[std::size_t(i)];
        const csm::ZExtensionAudit a = csm::auditZExtension(fit, casters, s.cascades.zExtension);
        CascadeStats& c = stats.cascades[std::size_t(i)];
        c.zExtensionUsed = a.used;
        c.zExtensionMinimal = a.minimal;
        c.zExtensionCuts = a.cuts;
        c.samplesFitted = fit.fittedToSamples;
    }
}

void Renderer::shadowPass(const Settings& s, FrameStats& stats) {
    gpu::DebugGroup group("shadow pass");
    const bool pancake = s.cascades.zExtension == ZExtension::Pancake;
    gpu::PassState state;
    state.depthTest = state.depthWrite = true;
    state.cullFace = casterCullFace(s.cascades.casterFaces);
    state.depthClamp = pancake;
    state.colorWrite = false;  // depth only
    glUseProgram(depthProgram_->id());
    if (options_.naive) scene_.bindGeometry();
    else scene_.bindClusteredGeometry();
    frameBlock_.bind(ST_BLOCK_FRAME);
    viewBlock_.bind(ST_BLOCK_VIEW);
    cache_.beginFrame(s, options_.cacheMaps && !options_.naive);
    for (int i = 0; i < s.cascades.count; ++i) {
        const std::string name = "cascade " + std::to_string(i);
        gpu::DebugGroup cascadeGroup(name.c_str());
        CascadeStats cs;
        timers_.begin(i);
        counters_.begin(i);
        PassWork& own = ownWork_[std::size_t(i)];
        if (options_.naive) naiveCascadeCasters(s, i, state, cs, own);
        else cascadeCasters(s, i, state, cs, own);
        counters_.end(i);
        timers_.end(i);
        const csm::CascadeFit& fit = plan_.cascades[i];  // after: a kept map may bring its own
        cs.vsNear = fit.vsNear;
        cs.vsFar = fit.vsFar;
        cs.lsExtent = fit.lsBox.extent();
        cs.texelWorldSize = fit.texelWorldSize;
        cs.mapSize = fit.mapSize;
        stats.cascades.push_back(cs);
    }
}

void Renderer::bindShadingInputs() const {
    frameBlock_.bind(ST_BLOCK_FRAME);
    cascadeBlock_.bind(ST_BLOCK_CASCADES);
    shadowMaps_.bindForSampling();
    if (moments_.layers() > 0) moments_.bindForSampling();
}

void Renderer::renderSideView(const Settings& s, const OrbitCamera& orbit, OffscreenTarget& out) {
    timers_.beginFrame(s.cascades.count + 1);
    counters_.beginFrame(CounterSlots{s.cascades.count}.total());  // counted, never read
    ownWork_.assign(std::size_t(CounterSlots{s.cascades.count}.total()), PassWork{});
    sidePass(s, orbit, out);
}

void Renderer::renderMainView(const Settings& s, OffscreenTarget& out) {
    timers_.beginFrame(s.cascades.count + 1);
    counters_.beginFrame(CounterSlots{s.cascades.count}.total());  // counted, never read
    ownWork_.assign(std::size_t(CounterSlots{s.cascades.count}.total()), PassWork{});
    const bool screen = screenShadowOn(s.filter);
    if (screen) buildScreenShadow(s, plan_.csProj * plan_.vsView, out.width(), out.height());
    mainPass(s, plan_.csProj * plan_.vsView, out, screen);
}

void Renderer::buildScreenShadow(const Settings& s, const glm::mat4& viewProj, int width, int height) {
    if (!screen_) screen_ = std::make_unique<ScreenShadow>();
    bindShadingInputs();
    const CounterSlots slots{s.cascades.count};
    // The mask pass's counters from its setup to its last draw; the blurs' from there on.
    counters_.begin(slots.mask());
    screen_->build(s, viewProj, width, height, [&] {
        drawVisible(viewProj);
        counters_.end(slots.mask());
        counters_.begin(slots.screenBlur());
    });
    counters_.end(slots.screenBlur());
    PassWork& mask = ownWork_[std::size_t(slots.mask())];
    mask.draws = visibleCommands_;
    mask.texelsCleared = pixels(width, height);
    mask.bytesWritten = pixels(width, height) * (8 + 4);  // RG32F mask and its D32F depth
    ownWork_[std::size_t(slots.screenBlur())] = screen_->blurWork(s.filter);
    shadowMaps_.unbindSamplers();
    glBindSampler(ST_BINDING_MOMENTS, 0);
}

void Renderer::sidePass(const Settings& s, const OrbitCamera& orbit, const OffscreenTarget& target) {
    csm::CameraParams cam = sideCamera(plan_, orbit, float(target.width()) / float(target.height()));
    glm::mat4 viewProj = csm::projectionMatrix(cam) * csm::viewMatrix(cam);
    sideBackground_ = true;
    mainPass(s, viewProj, target);
    sideBackground_ = false;
    lines_.draw(cascadeWireframes(plan_), viewProj, target.framebuffer(), target.width(), target.height());
    if (s.output.sideTexels) {
        const gpu_if::CascadeBlock block = cascadeBlock(s, plan_);  // the fits the maps were drawn with
        std::vector<glm::mat4> matrices;
        for (int i = 0; i < s.cascades.count; ++i) matrices.push_back(block.cascade[i].shadowMatrix);
        lines_.drawPoints(texelCloud(shadowMaps_, plan_, s.cascades.selection, matrices), viewProj, target.framebuffer(),
                          target.width(), target.height());
    }
}

void Renderer::mainPass(const Settings& s, const glm::mat4& viewProj, const OffscreenTarget& target, bool screen,
                        bool prepassed) {
    gpu::DebugGroup group("main pass");
    const CounterSlots slots{s.cascades.count};
    timers_.begin(s.cascades.count);
    counters_.begin(slots.main());
    gpu::PassState state = gpu::opaqueScenePass(target.framebuffer(), target.width(), target.height());
    if (prepassed) {
        // Both passes draw the same batches with the same invariant gl_Position, so each pixel's
        // nearest fragment passes LEQUAL and every fragment behind it fails before shading.
        state.depthFunc = GL_LEQUAL;
        state.depthWrite = false;
    }
    gpu::applyPassState(state);
    if (sideBackground_) glClearColor(0.16f, 0.17f, 0.2f, 1.0f);
    else glClearColor(0.62f, 0.72f, 0.85f, 1.0f);
    glClear(prepassed ? GL_COLOR_BUFFER_BIT : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Only the main camera's frame may go unshaded: the side view is an image to look at.
    const bool shade = options_.shadeMain || &target != &target_ || s.output.view == View::Side;
    glUseProgram(shade ? mainProgram_->id() : coverageProgram_->id());
    gpu_if::ViewBlock v = viewBlockOf(viewProj, target.width(), target.height(), options_.subpixelSteps);
    v.screenShadow = screen ? 1 : 0;
    viewBlock_.upload(v);
    viewBlock_.bind(ST_BLOCK_VIEW);
    bindShadingInputs();
    if (screen) screen_->bindForSampling();
    drawVisible(viewProj);
    shadowMaps_.unbindSamplers();
    glBindSampler(ST_BINDING_MOMENTS, 0);
    if (screen) screen_->unbind();
    counters_.end(slots.main());
    timers_.end(s.cascades.count);
    PassWork& own = ownWork_[std::size_t(slots.main())];
    own.draws = visibleCommands_;
    own.texelsCleared = pixels(target.width(), target.height());
}

}  // namespace st
