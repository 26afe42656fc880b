#pragma once
// Each cascade's depth layer rendered into a small RGBA8 texture with the depth range its own
// written texels span stretched to a visible grey ramp, for the editor's shadow-map viewer.
#include "renderer/gpu/gl.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/shadow_maps.h"

#include "shaders/interface.h"

#include <utility>
#include <vector>

namespace st {

class ShadowMapView {
public:
    ShadowMapView();
    // Re-renders every layer's tile (tileSize² texels each); the grey ramp spans the stored
    // depths the tile's own samples hold.
    void update(const ShadowMaps& maps, int tileSize);
    GLuint layerTexture(int layer) const { return tiles_[layer].id(); }
    int layers() const { return static_cast<int>(tiles_.size()); }
    // Stored depth (0 = the sun's side of the light box) of the nearest and farthest written
    // sample of the layer's tile; {0, 1} where nothing was written.
    std::pair<float, float> depthRange(int layer) const { return ranges_[std::size_t(layer)]; }

private:
    gpu::Program program_;
    gpu::VertexArray emptyVao_;
    gpu::Framebuffer fbo_;
    gpu::Sampler raw_;  // no depth compare: read the stored depth itself
    gpu::UniformBuffer<gpu_if::OverlayBlock> overlay_;
    std::vector<gpu::Texture> tiles_;
    // Tiles replaced by the last update(), kept one more update: a UI draw list recorded before
    // this frame's update() may still name them.
    std::vector<gpu::Texture> retired_;
    gpu::Texture rawTile_;  // R32F, tileSize²: the raw depths of one layer's samples
    std::vector<std::pair<float, float>> ranges_;
    int tileSize_ = 0;

    std::pair<float, float> writtenRange(int layer);
};

}  // namespace st
