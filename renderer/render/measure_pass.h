#pragma once
// The measurement pass: the scene drawn again with the main pass's coverage, writing world
// position, normal, the unfiltered and the filtered shadow result, the cascade and the texel
// density into float targets (shaders/measure.frag), then read back for the metrics.
#include "renderer/gpu/gl.h"
#include "renderer/render/shader_library.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/measure_samples.h"
#include "renderer/render/renderer.h"
#include "renderer/render/screen_shadow.h"
#include "renderer/settings/settings.h"
#include "shaders/interface.h"

#include <glm/mat4x4.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace st {

class MeasurePass {
public:
    MeasurePass();  // needs a current GL 4.5 core context

    // Draws the scene of `r` seen through observerViewProj at s.output's size, testing shadows
    // against the cascades and maps of r's last render(s). View depth for cascade selection
    // comes from that render's camera (the cascade camera), so the observer may stand elsewhere.
    MeasureSamples run(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj);

    // The same draw, reading back only MeasureSamples::shadow: what each frame of a camera path
    // needs (a quarter of the read-back).
    std::vector<glm::vec4> runShadowOnly(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj);

private:
    void ensureTargets(int width, int height);
    void draw(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj);
    void drawScene(const Renderer& r) const;
    std::vector<glm::vec4> read(const gpu::Texture& texture) const;

    SharedProgram program_;
    gpu::Texture targets_[4];  // position, normal, shadow, geometry (RGBA32F)
    gpu::Texture depth_;
    gpu::Framebuffer fbo_;
    gpu::UniformBuffer<gpu_if::ViewBlock> view_;
    // filter.screenSpace: the mask drawn with this pass's own draws and observer at its size, by
    // the renderer's code, so the factor scored is the one the image of that camera shows.
    std::unique_ptr<ScreenShadow> screen_;
    int width_ = 0;
    int height_ = 0;
};

// Shadow-map texels written by the last shadow pass, per cascade (depth below the clear value
// 1): the texels that casters actually cover, as opposed to layers x mapSize^2.
std::vector<std::size_t> coveredShadowTexels(const ShadowMaps& maps);

}  // namespace st
