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

void ShadowMapView::drawCascade(const ShadowMaps& maps, int i, float lo, float hi, bool border) {
    const csm::MapTile& t = maps.tile(i);
    const csm::MapTexture& tex = maps.layout().textures[static_cast<std::size_t>(t.texture)];
    gpu_if::OverlayBlock tile;
    tile.layer = t.layer;
    tile.depthLo = lo;
    tile.depthHi = hi;
    tile.uvRect = csm::tileBounds(t, tex);
    tile.tileBorder = border ? 1 : 0;
    overlay_.upload(tile);
    overlay_.bind(ST_BLOCK_OVERLAY);
    glBindTextureUnit(ST_BINDING_DEPTH_VIEW, maps.texture(i));
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void ShadowMapView::update(const ShadowMaps& maps, int tileSize, const MomentMaps* moments) {
    gpu::DebugGroup group("shadow map view");
    retired_.clear();
    const bool showMoments = moments && maps.layout().storage == CascadeStorage::Array &&
                             moments->layers() == maps.cascades() && moments->size() == maps.tile(0).size;
    auto retire = [this](std::vector<gpu::Texture>& tiles) {
        retired_.push_back(std::move(tiles.back()));
        tiles.pop_back();
    };
    if (tileSize != tileSize_) {
        while (!tiles_.empty()) retire(tiles_);
        while (!varianceTiles_.empty()) retire(varianceTiles_);
        rawTile_ = gpu::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(rawTile_.id(), 1, GL_R32F, tileSize, tileSize);
    }
    tileSize_ = tileSize;
    const int varianceTiles = showMoments ? maps.cascades() : 0;
    while (int(tiles_.size()) > maps.cascades()) retire(tiles_);
    while (int(varianceTiles_.size()) > varianceTiles) retire(varianceTiles_);
    for (auto* tiles : {&tiles_, &varianceTiles_})
        while (int(tiles->size()) < (tiles == &tiles_ ? maps.cascades() : varianceTiles)) {
            tiles->push_back(gpu::createTexture(GL_TEXTURE_2D));
            glTextureStorage2D(tiles->back().id(), 1, GL_RGBA8, tileSize, tileSize);
        }
    glUseProgram(program_.id());
    glBindVertexArray(emptyVao_.id());
    glBindSampler(ST_BINDING_DEPTH_VIEW, raw_.id());
    gpu::PassState state;
    state.framebuffer = fbo_.id();
    state.viewport = {0, 0, tileSize, tileSize};
    gpu::applyPassState(state);
    ranges_.assign(std::size_t(maps.cascades()), {0.0f, 1.0f});
    for (int i = 0; i < maps.cascades(); ++i) {
        // The scene's bounds span far more depth than a cascade's casters (a 2 km terrain under
        // a 30 m cascade): the ramp spans what this tile shows instead.
        ranges_[std::size_t(i)] = writtenRange(maps, i);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, tiles_[static_cast<std::size_t>(i)].id(), 0);
        drawCascade(maps, i, ranges_[std::size_t(i)].first, ranges_[std::size_t(i)].second, false);
    }
    if (showMoments) drawMoments(*moments);
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
            drawCascade(maps, i, ranges_[std::size_t(i)].first, ranges_[std::size_t(i)].second, true);
        }
    }
    glBindSampler(ST_BINDING_DEPTH_VIEW, 0);
}

// Over each cascade's tile the moment map's first moment, as depth on the ramp of the tile's own
// depths (the moments are made from them), and beside it the spread (moment_view.frag).
void ShadowMapView::drawMoments(const MomentMaps& moments) {
    glUseProgram(momentProgram_.id());
    glBindTextureUnit(ST_BINDING_DEPTH_VIEW, moments.texture());
    for (std::size_t i = 0; i < tiles_.size(); ++i) {
        gpu_if::OverlayBlock tile;
        tile.layer = static_cast<int>(i);
        tile.depthLo = ranges_[i].first;
        tile.depthHi = ranges_[i].second;
        tile.uvRect = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
        for (int image = 0; image < 2; ++image) {
            tile.brightness = float(image);  // moment_view.frag: 0 the mean as depth, 1 the spread
            overlay_.upload(tile);
            overlay_.bind(ST_BLOCK_OVERLAY);
            const GLuint target = image == 0 ? tiles_[i].id() : varianceTiles_[i].id();
            glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target, 0);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glUseProgram(program_.id());
}

// The tile's samples drawn raw into rawTile_ and read back: the tile shows exactly these texels,
// so their range is the content the ramp should span.
std::pair<float, float> ShadowMapView::writtenRange(const ShadowMaps& maps, int cascade) {
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, rawTile_.id(), 0);
    drawCascade(maps, cascade, 0.0f, -1.0f, false);
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
