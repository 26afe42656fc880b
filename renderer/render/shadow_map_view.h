#pragma once
// Each cascade's depth layer rendered into a small RGBA8 texture with the depth range the scene
// occupies stretched to a visible grey ramp, for the editor's shadow-map viewer.
#include "renderer/csm/cascade_plan.h"
#include "renderer/gpu/gl.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/moment_maps.h"
#include "renderer/render/shadow_maps.h"

#include "shaders/interface.h"

#include <vector>

namespace st {

class ShadowMapView {
public:
    ShadowMapView();
    // Re-renders every layer's tile (tileSize² texels each). With `moments` (a moment filter's
    // maps of this frame, the frame's cascade block bound at ST_BLOCK_CASCADES) a tile shows the
    // first moment as depth and a second tile per layer its spread (varianceTexture).
    void update(const ShadowMaps& maps, const csm::CascadePlan& plan, const csm::Aabb& wsSceneBounds, int tileSize,
                const MomentMaps* moments = nullptr);
    GLuint layerTexture(int layer) const { return tiles_[layer].id(); }
    // The spread tile of a layer, 0 without moments.
    GLuint varianceTexture(int layer) const {
        return layer < int(varianceTiles_.size()) ? varianceTiles_[layer].id() : 0;
    }
    int layers() const { return static_cast<int>(tiles_.size()); }

private:
    gpu::Program program_;
    gpu::Program momentProgram_;
    gpu::VertexArray emptyVao_;
    gpu::Framebuffer fbo_;
    gpu::Sampler raw_;  // no depth compare: read the stored depth itself
    gpu::UniformBuffer<gpu_if::OverlayBlock> overlay_;
    std::vector<gpu::Texture> tiles_;
    std::vector<gpu::Texture> varianceTiles_;
    // Tiles replaced by the last update(), kept one more update: a UI draw list recorded before
    // this frame's update() may still name them.
    std::vector<gpu::Texture> retired_;
    int tileSize_ = 0;
};

}  // namespace st
