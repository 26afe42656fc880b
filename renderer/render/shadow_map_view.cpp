#include "renderer/render/shadow_map_view.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/render/shader_library.h"
#include "shaders/interface.h"

#include <algorithm>

namespace st {

ShadowMapView::ShadowMapView() {
    program_ = linkShaderFiles("fullscreen.vert", "depth_view.frag", "depth_view");
    momentProgram_ = linkShaderFiles("fullscreen.vert", "moment_view.frag", "moment_view");
    emptyVao_ = gpu::createVertexArray();
    fbo_ = gpu::createFramebuffer();
    raw_ = gpu::createSampler();
    glSamplerParameteri(raw_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(raw_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

void ShadowMapView::update(const ShadowMaps& maps, const csm::CascadePlan& plan, const csm::Aabb& wsSceneBounds,
                           int tileSize, const MomentMaps* moments) {
    gpu::DebugGroup group("shadow map view");
    retired_.clear();
    const bool showMoments = moments && moments->layers() == maps.layers() && moments->size() == maps.size();
    auto retire = [this](std::vector<gpu::Texture>& tiles) {
        retired_.push_back(std::move(tiles.back()));
        tiles.pop_back();
    };
    if (tileSize != tileSize_) {
        while (!tiles_.empty()) retire(tiles_);
        while (!varianceTiles_.empty()) retire(varianceTiles_);
    }
    tileSize_ = tileSize;
    const int varianceLayers = showMoments ? maps.layers() : 0;
    while (int(tiles_.size()) > maps.layers()) retire(tiles_);
    while (int(varianceTiles_.size()) > varianceLayers) retire(varianceTiles_);
    for (auto* tiles : {&tiles_, &varianceTiles_})
        while (int(tiles->size()) < (tiles == &tiles_ ? maps.layers() : varianceLayers)) {
            tiles->push_back(gpu::createTexture(GL_TEXTURE_2D));
            glTextureStorage2D(tiles->back().id(), 1, GL_RGBA8, tileSize, tileSize);
        }
    glUseProgram(showMoments ? momentProgram_.id() : program_.id());
    glBindVertexArray(emptyVao_.id());
    glBindTextureUnit(ST_BINDING_DEPTH_VIEW, showMoments ? moments->texture() : maps.texture());
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
        overlay_.bind(ST_BLOCK_OVERLAY);
        for (int image = 0; image < (showMoments ? 2 : 1); ++image) {
            tile.brightness = float(image);  // moment_view.frag: 0 the mean as depth, 1 the spread
            overlay_.upload(tile);
            const GLuint target = image == 0 ? tiles_[i].id() : varianceTiles_[i].id();
            glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target, 0);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glBindSampler(ST_BINDING_DEPTH_VIEW, 0);
}

}  // namespace st
