#include "renderer/render/shadow_map_view.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/render/shader_library.h"
#include "shaders/interface.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

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

void ShadowMapView::drawCascade(const ShadowMaps& maps, int i, const Ramp& ramp, bool border) {
    const csm::MapTile& t = maps.tile(i);
    const csm::MapTexture& tex = maps.layout().textures[static_cast<std::size_t>(t.texture)];
    gpu_if::OverlayBlock tile;
    tile.layer = t.layer;
    tile.depthLo = ramp.lo;
    tile.depthHi = ramp.hi;
    tile.depthPlane = ramp.plane;
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
    ranges_.assign(std::size_t(maps.cascades()), Ramp{});
    for (int i = 0; i < maps.cascades(); ++i) {
        // The scene's bounds span far more depth than a cascade's casters (a 2 km terrain under
        // a 30 m cascade): the ramp spans what this tile shows instead.
        ranges_[std::size_t(i)] = writtenRange(maps, i);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, tiles_[static_cast<std::size_t>(i)].id(), 0);
        drawCascade(maps, i, ranges_[std::size_t(i)], false);
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
            drawCascade(maps, i, ranges_[std::size_t(i)], true);
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
        tile.depthLo = ranges_[i].rawLo;  // moment_view.frag: the mean on the stored depths' ramp
        tile.depthHi = ranges_[i].rawHi;
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

// The tile's samples drawn raw into rawTile_ and read back: the tile shows exactly these texels.
// Their mean plane (least squares over the written texels, in the tile's uv) is taken out, and the
// ramp spans the 1st to 99th percentile of what is left, not its extremes: a 2 km terrain sloping
// across the light's view otherwise fills the grey range with one gradient and leaves the casters
// on it nearly flat (issue 39 #9).
ShadowMapView::Ramp ShadowMapView::writtenRange(const ShadowMaps& maps, int cascade) {
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, rawTile_.id(), 0);
    drawCascade(maps, cascade, Ramp{0.0f, -1.0f, glm::vec4(0.0f), 0.0f, -1.0f}, false);
    const std::size_t n = std::size_t(tileSize_);
    std::vector<float> depth(n * n);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(rawTile_.id(), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    glm::dmat3 ata(0.0);
    glm::dvec3 atb(0.0);
    std::size_t written = 0;
    for (std::size_t y = 0; y < n; ++y)
        for (std::size_t x = 0; x < n; ++x) {
            const float d = depth[y * n + x];
            if (d >= 1.0f) continue;
            const glm::dvec3 row((double(x) + 0.5) / double(n), (double(y) + 0.5) / double(n), 1.0);
            ata += glm::outerProduct(row, row);
            atb += row * double(d);
            ++written;
        }
    if (written == 0) return {};
    glm::vec4 plane(0.0f);
    if (written >= 3 && std::abs(glm::determinant(ata)) > 1e-12) plane = glm::vec4(glm::vec3(glm::inverse(ata) * atb), 0.0f);
    float rawLo = 1.0f, rawHi = 0.0f;
    for (const float d : depth)
        if (d < 1.0f) rawLo = std::min(rawLo, d), rawHi = std::max(rawHi, d);
    std::vector<float> above;
    above.reserve(written);
    for (std::size_t y = 0; y < n; ++y)
        for (std::size_t x = 0; x < n; ++x)
            if (const float d = depth[y * n + x]; d < 1.0f)
                above.push_back(d - (plane.x * (float(x) + 0.5f) / float(n) + plane.y * (float(y) + 0.5f) / float(n) + plane.z));
    const auto at = [&](double share) {
        const auto k = std::size_t(share * double(above.size() - 1));
        std::nth_element(above.begin(), above.begin() + std::ptrdiff_t(k), above.end());
        return above[k];
    };
    const float lo = at(0.01), hi = at(0.99);
    return {lo, std::max(hi, lo + 1e-6f), plane, rawLo, std::max(rawHi, rawLo + 1e-6f)};
}

}  // namespace st
