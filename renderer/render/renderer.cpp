#include "renderer/render/renderer.h"

#include "renderer/csm/culling.h"
#include "renderer/render/shader_blocks.h"
#include "renderer/render/shader_library.h"

#include <chrono>
#include <string>

namespace st {

Renderer::Renderer(const Scene& scene) : scene_(scene) {
    depthProgram_ = linkShaderFiles("shadow_depth.vert", "shadow_depth.frag", "shadow_depth");
    mainProgram_ = linkShaderFiles("main.vert", "main.frag", "main");
}

FrameStats Renderer::render(const Settings& s, const OrbitCamera& orbit) {
    auto t0 = std::chrono::steady_clock::now();
    FrameStats stats;
    stats.width = s.output.width;
    stats.height = s.output.height;
    stats.sceneTriangles = scene_.scene().triangleCount();
    float aspect = float(s.output.width) / float(s.output.height);
    plan_ = csm::planCascades(s, aspect, scene_.scene().wsBounds);
    stats.splits = plan_.splits;
    target_.ensure(s.output.width, s.output.height);
    shadowMaps_.ensure(s.cascades.count, s.cascades.mapSize);
    stats.shadowMapBytes = shadowMaps_.bytes();
    frameBlock_.upload(frameBlock(s, plan_));
    cascadeBlock_.upload(cascadeBlock(s, plan_));
    timers_.beginFrame(s.cascades.count + 2);
    shadowPass(s, stats);
    const bool moments = isMomentFilter(s.filter.kind);
    if (moments) {
        timers_.begin(s.cascades.count + 1);
        cascadeBlock_.bind(ST_BLOCK_CASCADES);
        moments_.build(shadowMaps_, s);
        timers_.end(s.cascades.count + 1);
        stats.filterMapBytes = moments_.bytes();
    }
    if (s.output.view == View::Side)
        sidePass(s, orbit, target_);
    else
        mainPass(s, plan_.csProj * plan_.vsView, target_);
    stats.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    for (int i = 0; i < s.cascades.count; ++i) {
        stats.cascades[i].gpuMs = timers_.milliseconds(i);
        stats.gpuShadowMs += stats.cascades[i].gpuMs;
    }
    stats.gpuMainMs = timers_.milliseconds(s.cascades.count);
    if (moments) stats.gpuFilterMs = timers_.milliseconds(s.cascades.count + 1);
    return stats;
}

void Renderer::shadowPass(const Settings& s, FrameStats& stats) {
    gpu::DebugGroup group("shadow pass");
    const bool pancake = s.cascades.zExtension == ZExtension::Pancake;
    gpu::PassState state;
    state.framebuffer = shadowMaps_.framebuffer();
    state.viewport = {0, 0, shadowMaps_.size(), shadowMaps_.size()};
    state.depthTest = state.depthWrite = true;
    state.cullFace = GL_NONE;  // thin and open casters must cast from both sides
    state.depthClamp = pancake;
    state.colorWrite = false;  // depth only
    gpu::applyPassState(state);
    glUseProgram(depthProgram_.id());
    scene_.bindGeometry();
    frameBlock_.bind(ST_BLOCK_FRAME);
    viewBlock_.bind(ST_BLOCK_VIEW);
    for (int i = 0; i < s.cascades.count; ++i) {
        const std::string name = "cascade " + std::to_string(i);
        gpu::DebugGroup cascadeGroup(name.c_str());
        const csm::CascadeFit& fit = plan_.cascades[i];
        CascadeStats cs{fit.vsNear, fit.vsFar, fit.lsBox.extent(), fit.texelWorldSize};
        timers_.begin(i);
        shadowMaps_.attachLayer(i);
        glClear(GL_DEPTH_BUFFER_BIT);
        viewBlock_.upload({fit.viewProj});
        for (const DrawItem& item : scene_.scene().draws) {
            if (!csm::casterNeeded(item.wsBounds, fit, pancake)) continue;
            scene_.draw(item, FaceCulling::Keep);
            ++cs.casterDraws;
            cs.casterTriangles += item.indexCount / 3;
        }
        timers_.end(i);
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
    sidePass(s, orbit, out);
}

void Renderer::renderMainView(const Settings& s, OffscreenTarget& out) {
    timers_.beginFrame(s.cascades.count + 1);
    mainPass(s, plan_.csProj * plan_.vsView, out);
}

void Renderer::sidePass(const Settings& s, const OrbitCamera& orbit, const OffscreenTarget& target) {
    csm::CameraParams cam = sideCamera(plan_, orbit, float(target.width()) / float(target.height()));
    glm::mat4 viewProj = csm::projectionMatrix(cam) * csm::viewMatrix(cam);
    mainPass(s, viewProj, target);
    lines_.draw(cascadeWireframes(plan_), viewProj, target.framebuffer(), target.width(), target.height());
}

void Renderer::mainPass(const Settings& s, const glm::mat4& viewProj, const OffscreenTarget& target) {
    gpu::DebugGroup group("main pass");
    timers_.begin(s.cascades.count);
    gpu::applyPassState(gpu::opaqueScenePass(target.framebuffer(), target.width(), target.height()));
    glClearColor(0.62f, 0.72f, 0.85f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(mainProgram_.id());
    scene_.bindGeometry();
    viewBlock_.upload({viewProj});
    viewBlock_.bind(ST_BLOCK_VIEW);
    bindShadingInputs();
    for (const DrawItem& item : scene_.scene().draws) scene_.draw(item, FaceCulling::PerMaterial);
    glBindSampler(ST_BINDING_SHADOW_NEAREST, 0);
    glBindSampler(ST_BINDING_SHADOW_LINEAR, 0);
    glBindSampler(ST_BINDING_MOMENTS, 0);
    glBindSampler(ST_BINDING_SHADOW_RAW, 0);
    timers_.end(s.cascades.count);
}

}  // namespace st
