#include "renderer/render/measure_pass.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/image/flip_rows.h"
#include "renderer/render/shader_library.h"
#include "shaders/interface.h"

#include <algorithm>

namespace st {
MeasurePass::MeasurePass() {
    program_ = sharedShaderProgram("main.vert", "measure.frag", "measure");
}

void MeasurePass::ensureTargets(int width, int height) {
    if (fbo_ && width == width_ && height == height_) return;
    if (!fbo_) fbo_ = gpu::createFramebuffer();
    for (int i = 0; i < 4; ++i) {
        targets_[i] = gpu::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(targets_[i].id(), 1, GL_RGBA32F, width, height);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0 + i, targets_[i].id(), 0);
    }
    depth_ = gpu::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                               GL_COLOR_ATTACHMENT3};
    glNamedFramebufferDrawBuffers(fbo_.id(), 4, buffers);
    width_ = width;
    height_ = height;
}

void MeasurePass::drawScene(const Renderer& r) const {
    r.sceneGpu().bindGeometry();
    for (const DrawItem& item : r.sceneGpu().scene().draws) r.sceneGpu().draw(item, FaceCulling::PerMaterial);
}

// The main pass's state, so coverage is the same.
void MeasurePass::draw(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj) {
    const bool screen = screenShadowOn(s.filter);
    if (screen) {
        if (!screen_) screen_ = std::make_unique<ScreenShadow>();
        r.bindShadingInputs();
        screen_->build(s, observerViewProj, width_, height_, [&] { drawScene(r); });
    }
    gpu::applyPassState(gpu::opaqueScenePass(fbo_.id(), width_, height_));
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int i = 0; i < 4; ++i) glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, i, zero);
    const float far = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
    glUseProgram(program_->id());
    gpu_if::ViewBlock v;
    v.viewProj = observerViewProj;
    v.screenShadow = screen ? 1 : 0;
    view_.upload(v);
    view_.bind(ST_BLOCK_VIEW);
    r.bindShadingInputs();
    if (screen) screen_->bindForSampling();
    drawScene(r);
    r.shadowMaps().unbindSamplers();
    if (screen) screen_->unbind();
}

std::vector<glm::vec4> MeasurePass::read(const gpu::Texture& texture) const {
    std::vector<glm::vec4> pixels(std::size_t(width_) * height_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(glm::vec4)),
                      pixels.data());
    flipRows(std::span(pixels), std::size_t(width_));  // GL's first row is the bottom one
    return pixels;
}

MeasureSamples MeasurePass::run(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj) {
    gpu::DebugGroup group("measure pass");
    ensureTargets(s.output.width, s.output.height);
    draw(r, s, observerViewProj);
    return {width_, height_, read(targets_[0]), read(targets_[1]), read(targets_[2]), read(targets_[3])};
}

std::vector<glm::vec4> MeasurePass::runShadowOnly(const Renderer& r, const Settings& s,
                                                  const glm::mat4& observerViewProj) {
    gpu::DebugGroup group("measure pass (shadow only)");
    ensureTargets(s.output.width, s.output.height);
    draw(r, s, observerViewProj);
    return read(targets_[2]);
}

std::vector<std::size_t> coveredShadowTexels(const ShadowMaps& maps) {
    std::vector<std::size_t> covered;
    for (int i = 0; i < maps.cascades(); ++i) {
        const std::vector<float> depth = readCascadeDepth(maps, i);
        covered.push_back(static_cast<std::size_t>(
            std::count_if(depth.begin(), depth.end(), [](float d) { return d < 1.0f; })));
    }
    return covered;
}

}  // namespace st
