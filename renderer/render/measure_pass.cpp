#include "renderer/render/measure_pass.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/image/flip_rows.h"
#include "renderer/render/shader_blocks.h"
#include "renderer/render/shader_library.h"
#include "shaders/interface.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <string>

namespace st {
namespace {
// The members of `b` that choose a path through shadow_sampling.glsl, as measure_shadow.frag's
// compile-time constants (the values the renderer uploads, so the path is the image's).
std::string shadowDefines(const gpu_if::CascadeBlock& b, bool screen) {
    auto define = [](const char* name, auto value) { return "#define " + std::string(name) + " " + std::to_string(value) + "\n"; };
    std::string d = define("ST_SPEC_FILTER_KIND", b.filterKind) + define("ST_SPEC_STORAGE", b.storage) +
                    define("ST_SPEC_SELECTION", b.selection) + define("ST_SPEC_RECEIVER_PLANE", b.receiverPlane) +
                    define("ST_SPEC_SCREEN_SHADOW", screen ? 1 : 0);
    if (b.blendBand == 0.0f) d += "#define ST_SPEC_NO_BLEND\n";
    if (b.fadeBand == 0.0f) d += "#define ST_SPEC_NO_FADE\n";
    return d;
}

constexpr GLenum kColor[5] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3,
                              GL_COLOR_ATTACHMENT4};

gpu::Texture floatTarget(int width, int height) {
    gpu::Texture t = gpu::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_RGBA32F, width, height);
    return t;
}
}  // namespace

MeasurePass::MeasurePass(std::size_t surfaceBytes) : surfaceBudget_(surfaceBytes) {
    surfaceProgram_ = sharedShaderProgram("main.vert", "measure_surface.frag", "measure surface");
    emptyVao_ = gpu::createVertexArray();
}

// Four float targets on the GPU and, once read back, three copies: what a kept surface can take.
std::size_t MeasurePass::SurfaceKey::bytes() const {
    return 7 * std::size_t(width) * std::size_t(height) * sizeof(glm::vec4);
}

MeasurePass::Held MeasurePass::held() const {
    Held h{0, 0, surfaceWidth_, surfaceHeight_, shadowWidth_, shadowHeight_, screen_ ? screen_->bytes() : 0};
    for (const Surface& s : surfaces_) {
        const std::size_t px = std::size_t(s.key.width) * std::size_t(s.key.height);
        h.keptPixels += px;
        if (!s.readPosition.empty()) h.readBackPixels += px;
    }
    return h;
}

void MeasurePass::drawScene(const Renderer& r) const {
    r.sceneGpu().bindGeometry();
    for (const DrawItem& item : r.sceneGpu().scene().draws) r.sceneGpu().draw(item, FaceCulling::PerMaterial);
}

// The kept surface of `key`, moved to the front, or a new one drawn at the front. Before it is
// made, the least recently used are dropped until the new one fits in the budget with them
// (at 1920x1080 one takes 232 MB: the old one goes first, so the pass never holds two).
MeasurePass::Surface& MeasurePass::surfaceFor(const Renderer& r, const SurfaceKey& key) {
    const auto same = std::find_if(surfaces_.begin(), surfaces_.end(), [&](const Surface& s) { return s.key == key; });
    if (same != surfaces_.end()) {
        surfaces_.splice(surfaces_.begin(), surfaces_, same);
        ++surfacesReused_;
        return surfaces_.front();
    }
    std::size_t kept = key.bytes();
    for (auto it = surfaces_.begin(); it != surfaces_.end();) {
        kept += it->key.bytes();
        it = kept > surfaceBudget_ ? surfaces_.erase(it) : std::next(it);
    }
    static std::atomic<std::uint64_t> drawn{0};
    Surface fresh;
    fresh.key = key;
    fresh.serial = ++drawn;
    fresh.position = floatTarget(key.width, key.height);
    fresh.normal = floatTarget(key.width, key.height);
    fresh.dx = floatTarget(key.width, key.height);
    fresh.dy = floatTarget(key.width, key.height);
    surfaces_.push_front(std::move(fresh));
    drawSurface(r, surfaces_.front());
    ++surfacesDrawn_;
    return surfaces_.front();
}

// The main pass's state, so coverage is the same.
void MeasurePass::drawSurface(const Renderer& r, Surface& surface) {
    gpu::DebugGroup group("measure pass: surfaces");
    const int width = surface.key.width, height = surface.key.height;
    if (!surfaceFbo_) surfaceFbo_ = gpu::createFramebuffer();
    if (width != surfaceWidth_ || height != surfaceHeight_) {
        geometry_ = floatTarget(width, height);
        depth_ = gpu::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
        surfaceWidth_ = width, surfaceHeight_ = height;
    }
    const GLuint fbo = surfaceFbo_.id();
    const GLuint targets[5] = {surface.position.id(), surface.normal.id(), geometry_.id(), surface.dx.id(),
                               surface.dy.id()};
    for (int i = 0; i < 5; ++i) glNamedFramebufferTexture(fbo, kColor[i], targets[i], 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glNamedFramebufferDrawBuffers(fbo, 5, kColor);
    gpu::applyPassState(gpu::opaqueScenePass(fbo, width, height));
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int i = 0; i < 5; ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
    const float far = 1.0f;
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
    glUseProgram(surfaceProgram_->id());
    view_.upload(viewBlockOf(surface.key.observer, width, height, surface.key.subpixelSteps));
    view_.bind(ST_BLOCK_VIEW);
    r.bindShadingInputs();  // the frame block: the cascade camera's view and the sun
    drawScene(r);
    r.shadowMaps().unbindSamplers();
    surface.readPosition.clear(), surface.readNormal.clear();
    surface.readGeometry = read(geometry_, width, height);  // the shared target is drawn over next time
}

void MeasurePass::readSurface(Surface& surface) {
    if (!surface.readPosition.empty()) return;
    surface.readPosition = read(surface.position, surface.key.width, surface.key.height);
    surface.readNormal = read(surface.normal, surface.key.width, surface.key.height);
}

void MeasurePass::ensureShadowTarget(int width, int height) {
    if (shadowFbo_ && width == shadowWidth_ && height == shadowHeight_) return;
    if (!shadowFbo_) shadowFbo_ = gpu::createFramebuffer();
    shadow_ = floatTarget(width, height);
    glNamedFramebufferTexture(shadowFbo_.id(), GL_COLOR_ATTACHMENT0, shadow_.id(), 0);
    glNamedFramebufferDrawBuffer(shadowFbo_.id(), GL_COLOR_ATTACHMENT0);
    shadowWidth_ = width, shadowHeight_ = height;
}

void MeasurePass::drawShadow(const Renderer& r, const Settings& s, const Surface& surface) {
    const int width = surface.key.width, height = surface.key.height;
    const bool screen = screenShadowOn(s.filter);
    if (screen) {
        if (!screen_) screen_ = std::make_unique<ScreenShadow>();
        r.bindShadingInputs();
        screen_->build(s, surface.key.observer, width, height, [&] { drawScene(r); });
    }
    gpu::DebugGroup group("measure pass: shadows");
    ensureShadowTarget(width, height);
    gpu::PassState state;
    state.framebuffer = shadowFbo_.id();
    state.viewport = {0, 0, width, height};
    gpu::applyPassState(state);
    const std::string defines = shadowDefines(cascadeBlock(s, r.plan()), screen);
    SharedProgram& program = shadowPrograms_[defines];
    if (!program) program = sharedShaderProgram("fullscreen.vert", "measure_shadow.frag", "measure shadow", defines);
    glUseProgram(program->id());
    gpu_if::ViewBlock v;
    v.viewProj = surface.key.observer;
    v.screenShadow = screen ? 1 : 0;
    view_.upload(v);
    view_.bind(ST_BLOCK_VIEW);
    r.bindShadingInputs();
    if (screen) screen_->bindForSampling();
    const GLuint inputs[4] = {surface.position.id(), surface.normal.id(), surface.dx.id(), surface.dy.id()};
    const GLuint units[4] = {ST_BINDING_SURFACE_POSITION, ST_BINDING_SURFACE_NORMAL, ST_BINDING_SURFACE_DX,
                             ST_BINDING_SURFACE_DY};
    for (int i = 0; i < 4; ++i) glBindTextureUnit(units[i], inputs[i]);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    for (GLuint unit : units) glBindTextureUnit(unit, 0);
    r.shadowMaps().unbindSamplers();
    if (screen) screen_->unbind();
}

std::vector<glm::vec4> MeasurePass::read(const gpu::Texture& texture, int width, int height) const {
    std::vector<glm::vec4> pixels(std::size_t(width) * height);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(glm::vec4)),
                      pixels.data());
    flipRows(std::span(pixels), std::size_t(width));  // GL's first row is the bottom one
    return pixels;
}

MeasureSamples MeasurePass::run(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj) {
    gpu::DebugGroup group("measure pass");
    Surface& surface = surfaceFor(r, {r.sceneGpu().serial(), observerViewProj, r.plan().vsView, -r.plan().wsLightDir,
                                      s.output.width, s.output.height, r.options().subpixelSteps});
    readSurface(surface);
    drawShadow(r, s, surface);
    return {s.output.width, s.output.height, surface.readPosition, surface.readNormal,
            read(shadow_, s.output.width, s.output.height), surface.readGeometry, surface.serial};
}

std::vector<glm::vec4> MeasurePass::runShadowOnly(const Renderer& r, const Settings& s,
                                                  const glm::mat4& observerViewProj) {
    gpu::DebugGroup group("measure pass (shadow only)");
    const Surface& surface = surfaceFor(r, {r.sceneGpu().serial(), observerViewProj, r.plan().vsView,
                                            -r.plan().wsLightDir, s.output.width, s.output.height,
                                            r.options().subpixelSteps});
    drawShadow(r, s, surface);
    return read(shadow_, s.output.width, s.output.height);
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
