#pragma once
// Each cascade's depth map rendered into a small RGBA8 texture with the depth range its own
// written texels span stretched to a visible grey ramp, for the editor's shadow-map viewer; with
// the atlas storage also the whole atlas as one image, each tile outlined where it lies.
#include "renderer/gpu/gl.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/moment_maps.h"
#include "renderer/render/shadow_maps.h"

#include "shaders/interface.h"

#include <glm/vec4.hpp>

#include <utility>
#include <vector>

namespace st {

class ShadowMapView {
public:
    ShadowMapView();
    // Re-renders every cascade's tile (tileSize² texels each) and, for an atlas, the atlas image
    // (2 tileSize wide, the atlas's aspect); the grey ramp spans the stored depths the tile's own
    // samples hold. With `moments` (a moment filter's maps of this frame, array storage, the
    // frame's cascade block bound at ST_BLOCK_CASCADES) a tile shows the first moment as depth on
    // that ramp and a second tile per cascade its spread (varianceTexture).
    void update(const ShadowMaps& maps, int tileSize, const MomentMaps* moments = nullptr);
    GLuint layerTexture(int layer) const { return tiles_[layer].id(); }
    // The spread tile of a layer, 0 without moments.
    GLuint varianceTexture(int layer) const {
        return layer < int(varianceTiles_.size()) ? varianceTiles_[layer].id() : 0;
    }
    int layers() const { return static_cast<int>(tiles_.size()); }
    // Stored depth (0 = the sun's side of the light box) of the nearest and farthest written
    // sample of the cascade's tile; {0, 1} where nothing was written.
    // The stored depths the tile's written texels span (the moment tiles' ramp).
    std::pair<float, float> depthRange(int layer) const { return {ranges_[std::size_t(layer)].rawLo, ranges_[std::size_t(layer)].rawHi}; }
    GLuint atlasTexture() const { return atlas_.id(); }  // 0 unless the storage is an atlas
    int atlasWidth() const { return atlasWidth_; }
    int atlasHeight() const { return atlasHeight_; }

private:
    // Cascade i's tile into the bound framebuffer, its depth [lo, hi] as the grey ramp (hi < 0: raw).
    // A depth tile's grey ramp: depth above `plane` (x u + y v + z over the tile's uv) from lo
    // (bright) to hi (dark); rawLo..rawHi the stored depths themselves span.
    struct Ramp {
        float lo = 0.0f, hi = 1.0f;
        glm::vec4 plane{0.0f};
        float rawLo = 0.0f, rawHi = 1.0f;
    };
    void drawCascade(const ShadowMaps& maps, int i, const Ramp& ramp, bool border);
    void drawMoments(const MomentMaps& moments);
    gpu::Program program_;
    gpu::Program momentProgram_;
    gpu::VertexArray emptyVao_;
    gpu::Framebuffer fbo_;
    gpu::Sampler raw_;  // no depth compare: read the stored depth itself
    gpu::UniformBuffer<gpu_if::OverlayBlock> overlay_;
    std::vector<gpu::Texture> tiles_;
    gpu::Texture atlas_;
    int atlasWidth_ = 0;
    int atlasHeight_ = 0;
    std::vector<gpu::Texture> varianceTiles_;
    // Textures replaced by the last update(), kept one more update: a UI draw list recorded before
    // this frame's update() may still name them.
    std::vector<gpu::Texture> retired_;
    gpu::Texture rawTile_;  // R32F, tileSize²: the raw depths of one layer's samples
    std::vector<Ramp> ranges_;
    int tileSize_ = 0;

    Ramp writtenRange(const ShadowMaps& maps, int cascade);
};

}  // namespace st
