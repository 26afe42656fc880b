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

void ShadowMapView::drawCascade(const ShadowMaps& maps, const csm::CascadePlan& plan, const csm::Aabb& wsSceneBounds,
                                int i, bool border) {
    // Where the scene lies inside this light box, as stored depth (0 = the sun's side).
    const csm::CascadeFit& f = plan.cascades[static_cast<std::size_t>(i)];
    const csm::MapTile& t = maps.tile(i);
    const csm::MapTexture& tex = maps.layout().textures[static_cast<std::size_t>(t.texture)];
    csm::Aabb ls = csm::transformAabb(f.lsView, wsSceneBounds);
    float range = std::max(f.lsBox.extent().z, 1e-6f);
    gpu_if::OverlayBlock tile;
    tile.layer = t.layer;
    tile.depthLo = std::clamp((f.lsBox.max.z - ls.max.z) / range, 0.0f, 1.0f);
    tile.depthHi = std::clamp((f.lsBox.max.z - ls.min.z) / range, 0.0f, 1.0f);
    tile.uvRect = csm::tileBounds(t, tex);
    tile.tileBorder = border ? 1 : 0;
    overlay_.upload(tile);
    overlay_.bind(ST_BLOCK_OVERLAY);
    glBindTextureUnit(ST_BINDING_DEPTH_VIEW, maps.texture(i));
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void ShadowMapView::update(const ShadowMaps& maps, const csm::CascadePlan& plan, const csm::Aabb& wsSceneBounds,
                           int tileSize) {
    gpu::DebugGroup group("shadow map view");
    retired_.clear();
    auto retire = [this] {
        retired_.push_back(std::move(tiles_.back()));
        tiles_.pop_back();
    };
    if (tileSize != tileSize_)
        while (!tiles_.empty()) retire();
    tileSize_ = tileSize;
    while (int(tiles_.size()) > maps.cascades()) retire();
    while (int(tiles_.size()) < maps.cascades()) {
        tiles_.push_back(gpu::createTexture(GL_TEXTURE_2D));
        glTextureStorage2D(tiles_.back().id(), 1, GL_RGBA8, tileSize, tileSize);
    }
    glUseProgram(program_.id());
    glBindVertexArray(emptyVao_.id());
    glBindSampler(ST_BINDING_DEPTH_VIEW, raw_.id());
    gpu::PassState state;
    state.framebuffer = fbo_.id();
    state.viewport = {0, 0, tileSize, tileSize};
    gpu::applyPassState(state);
    for (int i = 0; i < maps.cascades(); ++i) {
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, tiles_[static_cast<std::size_t>(i)].id(), 0);
        drawCascade(maps, plan, wsSceneBounds, i, false);
    }
    const bool atlas = maps.layout().storage == CascadeStorage::Atlas;
    const csm::MapTexture extent = atlas ? maps.layout().textures.front() : csm::MapTexture{};
    const int w = atlas ? 2 * tileSize : 0;
    const int h = atlas ? std::max(1, w * extent.height / extent.width) : 0;
    if (atlas_ && (w != atlasWidth_ || h != atlasHeight_)) retired_.push_back(std::move(atlas_));
    atlasWidth_ = w;
    atlasHeight_ = h;
    if (atlas) {
        if (!atlas_) {
            atlas_ = gpu::createTexture(GL_TEXTURE_2D);
            glTextureStorage2D(atlas_.id(), 1, GL_RGBA8, w, h);
        }
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, atlas_.id(), 0);
        // The padding and any unused corner, darker than "never written" inside a tile.
        const float gap[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, gap);
        for (int i = 0; i < maps.cascades(); ++i) {
            const glm::vec4 b = csm::tileBounds(maps.tile(i), extent);
            const int x0 = int(b.x * float(w) + 0.5f), y0 = int(b.y * float(h) + 0.5f);
            const int x1 = int(b.z * float(w) + 0.5f), y1 = int(b.w * float(h) + 0.5f);
            state.viewport = {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
            gpu::applyPassState(state);
            drawCascade(maps, plan, wsSceneBounds, i, true);
        }
    }
    glBindSampler(ST_BINDING_DEPTH_VIEW, 0);
}

}  // namespace st
