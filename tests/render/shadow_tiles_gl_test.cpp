// Issue 13 item 5: the shadow-map tiles are normalised to their content. Each tile's grey ramp
// spans the depths its written texels hold (the scene's bounds span far more than one cascade's
// casters, which left the tiles flat grey), so every tile with casters shows both ends of the
// ramp; the range it reports lies within the written texels' range of the full layer.
#include "renderer/render/renderer.h"
#include "renderer/render/shadow_map_view.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings_json.h"
#include "tests/support/gl_fixture.h"

#include <algorithm>
#include <vector>

namespace st {
namespace {

class ShadowTilesGLTest : public test::GLTest {};

TEST_F(ShadowTilesGLTest, EveryTileSpansItsOwnDepthRange) {
    Settings s = loadPreset(ST_PRESET_DIR "/default.json");
    s.output.width = 160;
    s.output.height = 90;
    s.cascades.mapSize = 512;
    const Scene scene = loadScene(s.scene, ST_PRESET_DIR);
    Renderer renderer(scene);
    renderer.render(s);
    ShadowMapView tiles;
    constexpr int kTile = 64;
    tiles.update(renderer.shadowMaps(), kTile);
    ASSERT_EQ(tiles.layers(), s.cascades.count);
    const int size = renderer.shadowMaps().tile(0).size;  // the array storage: one size
    std::vector<float> depth(std::size_t(size) * std::size_t(size));
    std::vector<std::uint8_t> rgba(std::size_t(kTile) * kTile * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int layer = 0; layer < tiles.layers(); ++layer) {
        SCOPED_TRACE("cascade " + std::to_string(layer));
        glGetTextureSubImage(renderer.shadowMaps().texture(), 0, 0, 0, layer, size, size, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                             GLsizei(depth.size() * sizeof(float)), depth.data());
        float lo = 1.0f, hi = 0.0f;
        for (const float d : depth)
            if (d < 1.0f) lo = std::min(lo, d), hi = std::max(hi, d);
        ASSERT_LT(lo, hi) << "casters in every cascade of the yard";
        const auto [tileLo, tileHi] = tiles.depthRange(layer);
        EXPECT_GE(tileLo, lo);
        EXPECT_LE(tileHi, hi);
        EXPECT_GT(tileHi - tileLo, 0.5f * (hi - lo)) << "the tile samples most of the layer's depth range";
        glGetTextureImage(tiles.layerTexture(layer), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
        int brightest = 0, darkest = 255;
        for (std::size_t i = 0; i < rgba.size(); i += 4) {
            if (rgba[i] != rgba[i + 2]) continue;  // the blue of unwritten texels
            brightest = std::max<int>(brightest, rgba[i]);
            darkest = std::min<int>(darkest, rgba[i]);
        }
        EXPECT_GE(brightest, 250) << "the nearest caster at the bright end";
        EXPECT_LE(darkest, 45) << "the farthest at the dark end (0.15 grey)";
    }
}

}  // namespace
}  // namespace st
