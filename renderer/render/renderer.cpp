#include "renderer/render/renderer.h"

#include "renderer/csm/conventions.h"
#include "renderer/csm/culling.h"
#include "renderer/render/shader_library.h"
#include "renderer/render/shadow_uniforms.h"
#include "shaders/limits.h"

#include <glm/gtc/type_ptr.hpp>

#include <chrono>

namespace st {
namespace {
GLint loc(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

int viewCode(View v) {
    switch (v) {
    case View::Cascades: return ST_VIEW_CASCADES;
    case View::Shadow: return ST_VIEW_SHADOW;
    case View::TexelDensity: return ST_VIEW_TEXEL_DENSITY;
    default: return ST_VIEW_SHADED;
    }
}
}  // namespace

Renderer::Renderer(const Scene& scene) : scene_(scene) {
    depthProgram_ = gpu::linkProgram(shaderSource("shadow_depth.vert"),
                                     shaderSource("shadow_depth.frag"), "shadow_depth");
    mainProgram_ = gpu::linkProgram(shaderSource("main.vert"), shaderSource("main.frag"), "main");
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
    timers_.beginFrame(s.cascades.count + 1);
    scene_.bindGeometry();
    shadowPass(s, stats);
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
    return stats;
}

void Renderer::shadowPass(const Settings& s, FrameStats& stats) {
    gpu::DebugGroup group("shadow pass");
    GLuint prog = depthProgram_.id();
    glUseProgram(prog);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // thin and open casters must cast from both sides
    bool pancake = s.cascades.zExtension == ZExtension::Pancake;
    if (pancake) glEnable(GL_DEPTH_CLAMP);
    for (int i = 0; i < s.cascades.count; ++i) {
        const csm::CascadeFit& fit = plan_.cascades[i];
        CascadeStats cs{fit.vsNear, fit.vsFar, fit.lsBox.extent(), fit.texelWorldSize};
        timers_.begin(i);
        shadowMaps_.bindLayerForWriting(i);
        glClear(GL_DEPTH_BUFFER_BIT);
        glProgramUniformMatrix4fv(prog, loc(prog, "uViewProj"), 1, GL_FALSE, glm::value_ptr(fit.viewProj));
        for (const DrawItem& item : scene_.scene().draws) {
            if (!csm::casterNeeded(item.wsBounds, fit, pancake)) continue;
            scene_.draw(prog, item, false);
            ++cs.casterDraws;
            cs.casterTriangles += item.indexCount / 3;
        }
        timers_.end(i);
        stats.cascades.push_back(cs);
    }
    glDisable(GL_DEPTH_CLAMP);
}

void Renderer::setShadowUniforms(const Settings& s) const { st::setShadowUniforms(mainProgram_.id(), s, plan_); }

void Renderer::renderSideView(const Settings& s, const OrbitCamera& orbit, OffscreenTarget& out) {
    timers_.beginFrame(s.cascades.count + 1);
    scene_.bindGeometry();
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
    target.bind();
    lines_.draw(cascadeWireframes(plan_), viewProj);
}

void Renderer::mainPass(const Settings& s, const glm::mat4& viewProj, const OffscreenTarget& target) {
    gpu::DebugGroup group("main pass");
    GLuint p = mainProgram_.id();
    timers_.begin(s.cascades.count);
    target.bind();
    glClearColor(0.62f, 0.72f, 0.85f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(p);
    scene_.bindGeometry();
    glm::vec3 toSun = -plan_.wsLightDir;
    glProgramUniformMatrix4fv(p, loc(p, "uView"), 1, GL_FALSE, glm::value_ptr(plan_.vsView));
    glProgramUniformMatrix4fv(p, loc(p, "uViewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
    glProgramUniform3fv(p, loc(p, "uWsToSun"), 1, glm::value_ptr(toSun));
    glProgramUniform1f(p, loc(p, "uIntensity"), s.light.intensity);
    glProgramUniform1f(p, loc(p, "uAmbient"), s.light.ambient);
    glProgramUniform1i(p, loc(p, "uViewMode"), viewCode(s.output.view));
    setShadowUniforms(s);
    shadowMaps_.bindForSampling();
    glCullFace(GL_BACK);
    for (const DrawItem& item : scene_.scene().draws) scene_.draw(p, item, true);
    glDisable(GL_CULL_FACE);
    glBindSampler(ST_BINDING_SHADOW_NEAREST, 0);
    glBindSampler(ST_BINDING_SHADOW_LINEAR, 0);
    timers_.end(s.cascades.count);
}

}  // namespace st
