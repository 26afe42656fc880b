#pragma once
// The bytes of every texture and buffer the editor's GL objects hold, each computed from its
// dimensions and format (issue 39 #10). On llvmpipe they live in the process's own memory, so
// with the CPU side (the scene's copy, the ray caster's BVH, the driver) they make up its
// resident set. No GL: viewport_renderer.cpp fills the inputs from its objects.
#include "renderer/csm/storage_layout.h"
#include "ui/memory_view.h"

#include <cstddef>
#include <string>
#include <vector>

namespace st::app {

struct Extent {
    int width = 0, height = 0;
    std::size_t pixels() const { return std::size_t(width > 0 ? width : 0) * std::size_t(height > 0 ? height : 0); }
};

// A measurement pass (renderer/render/measure_pass.h, MeasurePass::Held) as it stands.
struct MeasureHeld {
    std::string what;                // "Accuracy and probe"
    std::size_t keptPixels = 0;      // surfaces kept for reuse: position, normal, dx, dy RGBA32F on the
                                     // GPU and the geometry's vec4 read back, per pixel
    std::size_t readBackPixels = 0;  // ... of which position and normal are read back too (2 vec4)
    Extent surface;                  // its shared targets: geometry RGBA32F + depth D32F
    Extent shadow;                   // its shadow target: RGBA32F
    std::size_t samplesPixels = 0;   // MeasureSamples copies held by its users (4 vec4 a pixel)
};

struct MemoryInputs {
    Extent scene;                    // the renderer's target: RGBA8 colour + D32F depth
    Extent pip;                      // the picture-in-picture: RGBA8 + D32F
    Extent abImage;                  // A's image, once the split was on: RGBA8 + D32F
    csm::StorageLayout maps;         // D32F
    csm::StorageLayout previewMaps;  // the interactive preview's own smaller set, once one ran (D32F)
    std::size_t momentBytes = 0;     // MomentMaps::bytes() (0 without a moment filter)
    std::size_t screenShadowBytes = 0;  // ScreenShadow::bytes() of the renderer and the passes
    int tileSize = 0;                // the shadow-map viewer: RGBA8 tiles and one R32F raw tile
    int tiles = 0;                   // ... depth and variance tiles
    Extent atlas;                    // ... the atlas image (RGBA8), 0 unless an atlas
    std::vector<MeasureHeld> measures;
    Extent overlay;                  // the error overlay (RGBA8)
    std::size_t vertices = 0;        // scene vertices (position, normal, uv: 32 B)
    std::size_t indices = 0;         // 32-bit indices, drawn as items
    std::size_t clusteredIndices = 0;  // ... and again in cluster order
    std::vector<Extent> images;      // the scene's textures: SRGB8_ALPHA8 with a full mip chain
};

// Bytes of a texture of `pixels` texels per level 0 with a full mip chain: about 4/3, summed exactly.
std::size_t mipChainTexels(Extent e);

// One line per kind of object (the ones holding nothing left out), largest first.
std::vector<ui::MemoryLine> memoryBreakdown(const MemoryInputs& in);

// The resident set of this process from /proc/self/statm; 0 where it is not available.
std::size_t residentBytes();

}  // namespace st::app
