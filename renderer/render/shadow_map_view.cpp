#include "renderer/render/shadow_map_view.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/render/shader_library.h"
#include "shaders/interface.h"

#include <algorithm>

namespace st {

ShadowMapView::ShadowMapView() {
    program_ = linkShaderFiles("fullscreen.vert", "depth_view.frag", "depth_view");
    emptyVao_ = gpu::createVertexArray();
    fbo_ = gpu::createFramebuffer();
    raw_ = gpu::createSampler();
    glSamplerParameteri(raw_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

void ShadowMapView::update(const ShadowMaps& maps, int tileSize) {
    gpu::DebugGroup group("shadow map view");
    retired_.clear();
    auto retire = [this] {
        retired_.push_back(std::move(tiles_.back()));
        tiles_.pop_back();
    };
    if (tileSize != tileSize_) {
        while (!tiles_.empty()) retire();
        rawTile_ = gpu::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(rawTile_.id(), 1, GL_R32F, tileSize, tileSize);
    }
    tileSize_ = tileSize;
    while (int(tiles_.size()) > maps.layers()) retire();
    while (int(tiles_.size()) < maps.layers()) {
        tiles_.push_back(gpu::createTexture(GL_TEXTURE_2D));
        glTextureStorage2D(tiles_.back().id(), 1, GL_RGBA8, tileSize, tileSize);
    }
    glUseProgram(program_.id());
    glBindVertexArray(emptyVao_.id());
    glBindTextureUnit(ST_BINDING_DEPTH_VIEW, maps.texture());
    glBindSampler(ST_BINDING_DEPTH_VIEW, raw_.id());
    gpu::PassState state;
    state.framebuffer = fbo_.id();
    state.viewport = {0, 0, tileSize, tileSize};
    gpu::applyPassState(state);
    ranges_.assign(std::size_t(maps.layers()), {0.0f, 1.0f});
    for (int i = 0; i < maps.layers(); ++i) {
        // The scene's bounds span far more depth than a cascade's casters (a 2 km terrain under
        // a 30 m cascade): the ramp spans what this tile shows instead.
        ranges_[std::size_t(i)] = writtenRange(i);
        gpu_if::OverlayBlock tile;
        tile.layer = i;
        tile.depthLo = ranges_[std::size_t(i)].first;
        tile.depthHi = ranges_[std::size_t(i)].second;
        overlay_.upload(tile);
        overlay_.bind(ST_BLOCK_OVERLAY);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, tiles_[i].id(), 0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindSampler(ST_BINDING_DEPTH_VIEW, 0);
}

// The tile's samples drawn raw into rawTile_ and read back: the tile shows exactly these texels,
// so their range is the content the ramp should span.
std::pair<float, float> ShadowMapView::writtenRange(int layer) {
    gpu_if::OverlayBlock raw;
    raw.layer = layer;
    raw.depthLo = 0.0f;
    raw.depthHi = -1.0f;
    overlay_.upload(raw);
    overlay_.bind(ST_BLOCK_OVERLAY);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, rawTile_.id(), 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> depth(std::size_t(tileSize_) * std::size_t(tileSize_));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(rawTile_.id(), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    float lo = 1.0f, hi = 0.0f;
    for (const float d : depth)
        if (d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
    if (lo > hi) return {0.0f, 1.0f};
    return {lo, std::max(hi, lo + 1e-6f)};
}

}  // namespace st
