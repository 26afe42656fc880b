#pragma once
// The measurement pass, in two halves. The surface pass draws the scene with the main pass's
// coverage and writes what each pixel's surface is (world position, normals, the position's
// screen derivatives, the view depth: shaders/measure_surface.frag); the shadow pass then tests
// every such pixel against the maps with the preset's filter and bias (measure_shadow.frag). Both
// are read back as floats for the metrics.
//
// Why two: nothing the surface pass writes depends on a shadow setting, so a view keeps its
// surfaces while a sweep or a tune changes the filter, bias, cascades or maps, and each candidate
// costs one fullscreen pass and one read-back instead of drawing the scene again with four float
// targets (truck-town, 640x360: 47 ms per view; docs/tuning.md#speed). The shadow pass takes the
// inputs main.frag's shading takes, stored as the floats they were, so its factor is the image's.
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
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace st {

class MeasurePass {
public:
    // Needs a current GL 4.5 core context. Keeps surfaces of at most surfaceBytes (kSurfaceBytes).
    explicit MeasurePass(std::size_t surfaceBytes = kSurfaceBytes);

    // Draws the scene of `r` seen through observerViewProj at s.output's size, testing shadows
    // against the cascades and maps of r's last render(s). View depth for cascade selection
    // comes from that render's camera (the cascade camera), so the observer may stand elsewhere.
    MeasureSamples run(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj);

    // The same, reading back only MeasureSamples::shadow: what each frame of a camera path needs.
    std::vector<glm::vec4> runShadowOnly(const Renderer& r, const Settings& s, const glm::mat4& observerViewProj);

    // Surface passes drawn and reused since construction (a reuse skips the scene draw).
    std::size_t surfacesDrawn() const { return surfacesDrawn_; }
    std::size_t surfacesReused() const { return surfacesReused_; }

    // What the pass holds now, for the editor's memory breakdown (issue 39 #10): the pixels of the
    // surfaces kept (four RGBA32F targets and the geometry's read-back vec4 each), of those whose
    // position and normal are read back too (two vec4), and the sizes of the shared targets
    // (geometry RGBA32F + depth D32F; shadow RGBA32F).
    struct Held {
        std::size_t keptPixels = 0, readBackPixels = 0;
        int surfaceWidth = 0, surfaceHeight = 0;
        int shadowWidth = 0, shadowHeight = 0;
        std::size_t screenShadowBytes = 0;
    };
    Held held() const;

    // Kept surfaces, most recently used first, while they take at most this many bytes (GPU and
    // read-back copies); the newest is always kept. A tune alternates between about five views
    // (26 MB each at 640x360).
    static constexpr std::size_t kSurfaceBytes = std::size_t(256) << 20;
    // What one surface of width x height takes, kept and read back.
    static std::size_t surfaceBytes(int width, int height) { return SurfaceKey{.width = width, .height = height}.bytes(); }

private:
    // What a surface pass's output depends on: the scene's geometry on the GPU, the observer, the
    // cascade camera's view (the view depth), the sun (N.L), the size and the rasterizer's grid.
    struct SurfaceKey {
        std::uint64_t scene = 0;  // SceneGpu::serial()
        glm::mat4 observer{1.0f};
        glm::mat4 cascadeView{1.0f};
        glm::vec3 toSun{0.0f};
        int width = 0;
        int height = 0;
        int subpixelSteps = 0;  // RenderOptions::subpixelSteps
        bool operator==(const SurfaceKey&) const = default;
        std::size_t bytes() const;  // what a surface of this size takes, kept and read back
    };
    struct Surface {
        SurfaceKey key;
        std::uint64_t serial = 0;  // MeasureSamples::surface
        gpu::Texture position, normal, dx, dy;  // what the shadow pass reads (RGBA32F)
        std::vector<glm::vec4> readPosition, readNormal, readGeometry;  // empty until first read back
    };

    Surface& surfaceFor(const Renderer& r, const SurfaceKey& key);
    void drawSurface(const Renderer& r, Surface& surface);
    void readSurface(Surface& surface);
    void drawShadow(const Renderer& r, const Settings& s, const Surface& surface);
    void ensureShadowTarget(int width, int height);
    void drawScene(const Renderer& r) const;
    std::vector<glm::vec4> read(const gpu::Texture& texture, int width, int height) const;

    SharedProgram surfaceProgram_;
    std::map<std::string, SharedProgram> shadowPrograms_;  // by their defines (shadowDefines in the .cpp)
    gpu::Texture geometry_;  // the surface pass's geometric normals: read back at once, so one target serves all
    gpu::Texture depth_;
    gpu::Framebuffer surfaceFbo_;
    int surfaceWidth_ = 0;
    int surfaceHeight_ = 0;
    gpu::Texture shadow_;
    gpu::Framebuffer shadowFbo_;
    int shadowWidth_ = 0;
    int shadowHeight_ = 0;
    gpu::VertexArray emptyVao_;
    std::list<Surface> surfaces_;
    gpu::UniformBuffer<gpu_if::ViewBlock> view_;
    // filter.screenSpace: the mask drawn with this pass's own draws and observer at its size, by
    // the renderer's code, so the factor scored is the one the image of that camera shows.
    std::unique_ptr<ScreenShadow> screen_;
    std::size_t surfaceBudget_;
    std::size_t surfacesDrawn_ = 0;
    std::size_t surfacesReused_ = 0;
};

// Shadow-map texels written by the last shadow pass, per cascade (depth below the clear value
// 1): the texels that casters actually cover, as opposed to layers x mapSize^2.
std::vector<std::size_t> coveredShadowTexels(const ShadowMaps& maps);

}  // namespace st
