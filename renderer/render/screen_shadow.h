#pragma once
// Seed 001's screen-space soft shadows (filter.screenSpace "blur"): the preset's filter evaluated
// once per pixel into a full-size mask (factor and view depth), downsampled to 1/N, blurred by a
// separable depth-aware Gaussian (horizontal, then vertical), upsampled joint-bilaterally to full
// size; the main and measurement passes then read that factor instead of sampling the maps
// (shaders/screen_*.{frag,glsl}). Depth-aware where the post's blur is not: a Gaussian of the
// relative depth difference weights every tap of the downsample, the blur and the upsample, so
// a near occluder's shadow does not bleed onto the background across a silhouette.
#include "renderer/gpu/gl.h"
#include "renderer/render/shader_library.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/gpu_timer.h"
#include "renderer/render/pass_work.h"
#include "renderer/settings/settings.h"
#include "shaders/interface.h"

#include <glm/mat4x4.hpp>

#include <array>
#include <cstddef>
#include <functional>

namespace st {

inline constexpr int kMaxScreenBlurRadius = 16;  // filter.screenBlurRadius's maximum

// The main and measurement passes read their factor from this path: for the blur, for contact
// shadows (filter.contact), or both. Contact shadows march through the mask pass's depth, then take
// min() with the map's factor (the blurred one, or the mask's own with no blur).
inline bool screenShadowOn(const FilterSettings& f) {
    return f.screenSpace != ScreenSpace::Off || f.contact != ContactShadows::Off;
}

// One-sided weights of taps 0..radius of the 1-D Gaussian, sigma = (radius + 1) / 2 pixels (the
// rule of the moment blur and the Gaussian PCF, renderer/csm/filter_weights.h), normalised so the
// taps -radius..radius sum to 1; the rest 0. Radius 0 is the single weight 1.
std::array<float, kMaxScreenBlurRadius + 1> screenBlurWeights(int radius);

// Size of the downsampled mask for an output of `full` pixels along one axis: ceil(full / n).
int screenLowSize(int full, int n);

// Bytes of the path's targets at width x height with downsample n: the mask (RG32F) and its depth
// buffer (D32F), two downsampled RG32F targets, the upsampled factor (R32F).
std::size_t screenShadowBytes(int width, int height, int n);

class ScreenShadow {
public:
    ScreenShadow();  // needs a current GL context: links the four programs

    // The mask of s.filter seen through viewProj at width x height, drawn by drawScene (which
    // binds geometry and issues the draws; the caller has bound the frame and cascade blocks and
    // the maps, as for the main pass), then downsampled, blurred and upsampled (filter.screenSpace),
    // then contact shadows marched (filter.contact). Leaves ST_BLOCK_VIEW bound to its own buffer:
    // the caller uploads and binds its view block after.
    void build(const Settings& s, const glm::mat4& viewProj, int width, int height,
               const std::function<void()>& drawScene);
    // The renderer's own counts of the last build()'s downsample, blurs and upsample for f: four
    // fullscreen draws; texel fetches at the shaders' full loop lengths (the downsample reads its
    // N x N block twice, each blur its centre and 2r + 1 taps, the upsample the full-size texel
    // and four downsampled ones); the three downsampled targets and the R32F result written.
    // With contact shadows, one more fullscreen draw: per pixel the map factor, the mask and the
    // depth, and two mask reads per step (at most: the march stops at its first hit); one R32F write.
    PassWork blurWork(const FilterSettings& f) const;
    void bindForSampling() const;  // the upsampled factor at ST_BINDING_SCREEN_SHADOW
    void unbind() const;
    GLuint maskTexture() const { return mask_.id(); }      // RG32F: factor, view depth (0: none)
    GLuint lowTexture() const { return low_[0].id(); }     // RG32F, 1/N size: blurred factor, depth
    GLuint resultTexture() const { return factor_; }       // the factor the image shows (.r)
    int width() const { return width_; }
    int height() const { return height_; }
    int downsample() const { return n_; }
    std::size_t bytes() const;
    // GPU time of the last build(): the mask pass (a scene draw that filters the maps), and the
    // downsample, both blurs and the upsample. Waits for the results.
    double maskMs() const { return timers_.milliseconds(0); }
    double blurMs() const { return timers_.milliseconds(1); }

private:
    void ensure(int width, int height, int n);
    void blur(const FilterSettings& f);
    void march(const Settings& s, const glm::mat4& viewProj, GLuint mapFactor);
    void fullscreen(GLuint target, int width, int height, GLuint source, const gpu::Program& program);
    SharedProgram maskProgram_;
    SharedProgram downProgram_;
    SharedProgram blurProgram_;
    SharedProgram upProgram_;
    SharedProgram contactProgram_;
    gpu::VertexArray emptyVao_;
    gpu::Framebuffer maskFbo_;
    gpu::Framebuffer passFbo_;
    gpu::Texture mask_;
    gpu::Texture depth_;
    gpu::Texture low_[2];
    gpu::Texture result_;
    gpu::Texture contact_;  // R32F: min(map factor, contact factor)
    GLuint factor_ = 0;     // what the passes read: contact_, result_ or the mask
    bool blurred_ = false, marched_ = false;  // what the last build() ran
    gpu::UniformBuffer<gpu_if::ScreenBlock> block_;
    gpu::UniformBuffer<gpu_if::ViewBlock> view_;
    GpuTimers timers_;
    int width_ = 0;
    int height_ = 0;
    int n_ = 0;
};

}  // namespace st
