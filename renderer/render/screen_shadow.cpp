#include "renderer/render/screen_shadow.h"

#include "renderer/csm/light_fit.h"
#include "renderer/gpu/pass_state.h"
#include "renderer/render/shader_library.h"

#include <glm/matrix.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace st {

std::array<float, kMaxScreenBlurRadius + 1> screenBlurWeights(int radius) {
    if (radius < 0 || radius > kMaxScreenBlurRadius)
        throw std::invalid_argument("screen blur radius " + std::to_string(radius) + " outside 0.." +
                                    std::to_string(kMaxScreenBlurRadius));
    std::array<float, kMaxScreenBlurRadius + 1> w{};
    const double sigma = 0.5 * (radius + 1);
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) sum += std::exp(-double(k * k) / (2.0 * sigma * sigma));
    for (int k = 0; k <= radius; ++k) w[std::size_t(k)] = float(std::exp(-double(k * k) / (2.0 * sigma * sigma)) / sum);
    return w;
}

int screenLowSize(int full, int n) { return (full + n - 1) / n; }

std::size_t screenShadowBytes(int width, int height, int n) {
    const auto full = std::size_t(width) * std::size_t(height);
    const auto low = std::size_t(screenLowSize(width, n)) * std::size_t(screenLowSize(height, n));
    return full * (8u + 4u + 4u) + 2u * low * 8u;
}

ScreenShadow::ScreenShadow() {
    maskProgram_ = sharedShaderProgram("main.vert", "screen_mask.frag", "screen_mask");
    downProgram_ = sharedShaderProgram("fullscreen.vert", "screen_down.frag", "screen_down");
    blurProgram_ = sharedShaderProgram("fullscreen.vert", "screen_blur.frag", "screen_blur");
    upProgram_ = sharedShaderProgram("fullscreen.vert", "screen_up.frag", "screen_up");
    contactProgram_ = sharedShaderProgram("fullscreen.vert", "screen_contact.frag", "screen_contact");
    emptyVao_ = gpu::createVertexArray();
    maskFbo_ = gpu::createFramebuffer();
    passFbo_ = gpu::createFramebuffer();
}

namespace {
gpu::Texture makeTarget(GLenum format, int width, int height, const char* label) {
    gpu::Texture t = gpu::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, width, height);
    glObjectLabel(GL_TEXTURE, t.id(), -1, label);
    return t;
}
}  // namespace

void ScreenShadow::ensure(int width, int height, int n) {
    if (mask_ && width == width_ && height == height_ && n == n_) return;
    if (width != width_ || height != height_ || !mask_) {
        mask_ = makeTarget(GL_RG32F, width, height, "screen shadow mask");
        depth_ = makeTarget(GL_DEPTH_COMPONENT32F, width, height, "screen shadow mask depth");
        result_ = makeTarget(GL_R32F, width, height, "screen shadow upsampled");
        contact_ = makeTarget(GL_R32F, width, height, "screen shadow with contact shadows");
        glNamedFramebufferTexture(maskFbo_.id(), GL_COLOR_ATTACHMENT0, mask_.id(), 0);
        glNamedFramebufferTexture(maskFbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        glNamedFramebufferDrawBuffer(maskFbo_.id(), GL_COLOR_ATTACHMENT0);
    }
    const int lw = screenLowSize(width, n), lh = screenLowSize(height, n);
    low_[0] = makeTarget(GL_RG32F, lw, lh, "screen shadow downsampled");
    low_[1] = makeTarget(GL_RG32F, lw, lh, "screen shadow blurred along x");
    width_ = width;
    height_ = height;
    n_ = n;
}

void ScreenShadow::fullscreen(GLuint target, int width, int height, GLuint source, const gpu::Program& program) {
    glNamedFramebufferTexture(passFbo_.id(), GL_COLOR_ATTACHMENT0, target, 0);
    glNamedFramebufferDrawBuffer(passFbo_.id(), GL_COLOR_ATTACHMENT0);
    gpu::PassState state;
    state.framebuffer = passFbo_.id();
    state.viewport = {0, 0, width, height};
    gpu::applyPassState(state);
    glBindTextureUnit(ST_BINDING_SCREEN_SOURCE, source);
    glUseProgram(program.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void ScreenShadow::build(const Settings& s, const glm::mat4& viewProj, int width, int height,
                         const std::function<void()>& drawScene) {
    gpu::DebugGroup group("screen-space shadow");
    const FilterSettings& f = s.filter;
    ensure(width, height, f.screenDownsample);
    timers_.beginFrame(2);
    timers_.begin(0);
    {
        gpu::DebugGroup maskGroup("mask");
        gpu::applyPassState(gpu::opaqueScenePass(maskFbo_.id(), width_, height_));
        const float clear[4] = {1.0f, 0.0f, 0.0f, 0.0f};  // lit, no surface
        glClearNamedFramebufferfv(maskFbo_.id(), GL_COLOR, 0, clear);
        const float far = 1.0f;
        glClearNamedFramebufferfv(maskFbo_.id(), GL_DEPTH, 0, &far);
        glUseProgram(maskProgram_->id());
        gpu_if::ViewBlock v;
        v.viewProj = viewProj;
        view_.upload(v);  // screenShadow 0: the mask filters the maps itself
        view_.bind(ST_BLOCK_VIEW);
        drawScene();
    }
    timers_.end(0);
    timers_.begin(1);
    blurred_ = f.screenSpace != ScreenSpace::Off;
    marched_ = f.contact != ContactShadows::Off;
    glBindSampler(ST_BINDING_SCREEN_SOURCE, 0);
    glBindSampler(ST_BINDING_SCREEN_FULL, 0);
    block_.bind(ST_BLOCK_SCREEN);
    if (blurred_) blur(f);
    factor_ = blurred_ ? result_.id() : mask_.id();
    if (marched_) {
        march(s, viewProj, factor_);
        factor_ = contact_.id();
    }
    timers_.end(1);
    glNamedFramebufferTexture(passFbo_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
    glBindTextureUnit(ST_BINDING_SCREEN_SOURCE, 0);
    glBindTextureUnit(ST_BINDING_SCREEN_FULL, 0);
    glBindTextureUnit(ST_BINDING_SCREEN_DEPTH, 0);
}

void ScreenShadow::blur(const FilterSettings& f) {
    gpu_if::ScreenBlock b;
    const auto w = screenBlurWeights(f.screenBlurRadius);
    for (std::size_t k = 0; k < w.size(); ++k) b.screenWeights[k / 4][int(k % 4)] = w[k];
    b.screenRadius = f.screenBlurRadius;
    b.screenDownsample = n_;
    b.screenDepthSigma = f.screenDepthSigma;
    const int lw = screenLowSize(width_, n_), lh = screenLowSize(height_, n_);
    block_.upload(b);
    fullscreen(low_[0].id(), lw, lh, mask_.id(), *downProgram_);
    b.screenAxis = 0;
    block_.upload(b);
    fullscreen(low_[1].id(), lw, lh, low_[0].id(), *blurProgram_);
    b.screenAxis = 1;
    block_.upload(b);
    fullscreen(low_[0].id(), lw, lh, low_[1].id(), *blurProgram_);
    glBindTextureUnit(ST_BINDING_SCREEN_FULL, mask_.id());
    fullscreen(result_.id(), width_, height_, low_[0].id(), *upProgram_);
}

void ScreenShadow::march(const Settings& s, const glm::mat4& viewProj, GLuint mapFactor) {
    gpu::DebugGroup group("contact shadows");
    gpu_if::ScreenBlock b;
    b.contactViewProj = viewProj;
    b.contactClipToWs = glm::inverse(viewProj);
    b.contactToSun = glm::vec4(-csm::lightDirection(s.light.azimuth, s.light.elevation), 0.0f);
    b.contactLength = s.filter.contactLength;
    b.contactSteps = s.filter.contactSteps;
    b.contactThickness = s.filter.contactThickness;
    block_.upload(b);
    glBindTextureUnit(ST_BINDING_SCREEN_FULL, mask_.id());
    glBindTextureUnit(ST_BINDING_SCREEN_DEPTH, depth_.id());
    glBindSampler(ST_BINDING_SCREEN_DEPTH, 0);
    fullscreen(contact_.id(), width_, height_, mapFactor, *contactProgram_);
}

std::size_t ScreenShadow::bytes() const {
    if (width_ <= 0) return 0;
    const std::size_t full = std::size_t(width_) * std::size_t(height_);
    std::size_t b = full * (8u + 4u);  // the mask and its depth
    if (blurred_) b = screenShadowBytes(width_, height_, n_);
    if (marched_) b += full * 4u;
    return b;
}

PassWork ScreenShadow::blurWork(const FilterSettings& f) const {
    const std::uint64_t full = std::uint64_t(width_) * std::uint64_t(height_);
    constexpr std::uint64_t kRg32f = 8, kR32f = 4;
    PassWork w;
    if (f.screenSpace != ScreenSpace::Off) {
        const std::uint64_t low = std::uint64_t(screenLowSize(width_, n_)) * std::uint64_t(screenLowSize(height_, n_));
        const std::uint64_t n2 = std::uint64_t(n_) * std::uint64_t(n_);
        const std::uint64_t blurTaps = 2u * std::uint64_t(f.screenBlurRadius) + 2u;  // centre and 2r + 1
        w.draws = 4;
        w.filterTaps = low * 2u * n2 + 2u * low * blurTaps + full * 5u;
        w.bytesRead = w.filterTaps * kRg32f;  // every source is RG32F
        w.bytesWritten = 3u * low * kRg32f + full * kR32f;
    }
    if (f.contact != ContactShadows::Off) {
        const std::uint64_t taps = full * (3u + std::uint64_t(f.contactSteps));
        w.draws += 1;
        w.filterTaps += taps;
        w.bytesRead += taps * kRg32f;
        w.bytesWritten += full * kR32f;
    }
    return w;
}

void ScreenShadow::bindForSampling() const {
    glBindTextureUnit(ST_BINDING_SCREEN_SHADOW, factor_);
    glBindSampler(ST_BINDING_SCREEN_SHADOW, 0);
}

void ScreenShadow::unbind() const { glBindTextureUnit(ST_BINDING_SCREEN_SHADOW, 0); }

}  // namespace st
