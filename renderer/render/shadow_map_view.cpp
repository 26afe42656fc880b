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
    for (int i = 0; i < maps.layers(); ++i) {
        // Where the scene lies inside this light box, as stored depth (0 = the sun's side).
        const csm::CascadeFit& f = plan.cascades[i];
        csm::Aabb ls = csm::transformAabb(f.lsView, wsSceneBounds);
        float range = std::max(f.lsBox.extent().z, 1e-6f);
        gpu_if::OverlayBlock tile;
        tile.layer = i;
        tile.depthLo = std::clamp((f.lsBox.max.z - ls.max.z) / range, 0.0f, 1.0f);
        tile.depthHi = std::clamp((f.lsBox.max.z - ls.min.z) / range, 0.0f, 1.0f);
        overlay_.upload(tile);
        overlay_.bind(ST_BLOCK_OVERLAY);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, tiles_[i].id(), 0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindSampler(ST_BINDING_DEPTH_VIEW, 0);
}

}  // namespace st
