#pragma once
// Draws one frame of a Settings value: a depth pass per cascade into a texture array, then the
// main pass into an offscreen colour target. Knows nothing about windows: headless replay reads
// the pixels back, the editor blits or shows the texture.
#include "renderer/csm/cascade_plan.h"
#include "renderer/gpu/gl.h"
#include "renderer/render/frame_stats.h"
#include "renderer/render/gpu_timer.h"
#include "renderer/render/scene_gpu.h"
#include "renderer/render/shadow_maps.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

#include <cstdint>
#include <vector>

namespace st {

class Renderer {
public:
    // Needs a current GL 4.5 core context; the scene must outlive the renderer.
    explicit Renderer(const Scene& scene);

    // Renders into the offscreen target, sized from s.output. Throws std::invalid_argument for
    // settings the cascade math rejects.
    FrameStats render(const Settings& s);

    std::vector<std::uint8_t> readRgba8() const;  // width*height*4, top row first
    GLuint colorTexture() const { return color_.id(); }
    GLuint framebuffer() const { return fbo_.id(); }
    GLuint shadowMapTexture() const { return shadowMaps_.texture(); }
    GLuint depthTexture() const { return depth_.id(); }  // main pass depth, D32F
    const csm::CascadePlan& plan() const { return plan_; }  // of the last render()
    const SceneGpu& sceneGpu() const { return scene_; }
    const ShadowMaps& shadowMaps() const { return shadowMaps_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void ensureTarget(int width, int height);
    void shadowPass(const Settings& s, FrameStats& stats);
    void mainPass(const Settings& s);
    void setShadowUniforms(const Settings& s) const;

    SceneGpu scene_;
    gpu::Program depthProgram_;
    gpu::Program mainProgram_;
    ShadowMaps shadowMaps_;
    GpuTimers timers_;
    gpu::Texture color_;
    gpu::Texture depth_;
    gpu::Framebuffer fbo_;
    int width_ = 0;
    int height_ = 0;
    csm::CascadePlan plan_;
};

}  // namespace st
