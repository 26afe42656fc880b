// Cascade storage (cascades.storage, cascades.mapSizes): the array, the atlas and one texture per
// cascade give the same image where their settings match, and per-cascade sizes render at their
// stated resolution.
#include "renderer/render/measure_pass.h"
#include "renderer/render/shadow_map_view.h"
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/image_compare.h"

#include <algorithm>
#include <vector>

using namespace st;

namespace {
class StorageGLTest : public test::GLTest {};

Settings yardAt(View view, FilterKind filter, Selection selection) {
    Settings s;  // the yard from the default camera, four cascades
    s.output = {320, 180, view};
    s.cascades.mapSize = 512;
    s.cascades.selection = selection;
    s.filter.kind = filter;
    s.filter.size = 5;
    return s;
}

std::size_t countIf(const std::vector<float>& depth, bool (*pred)(float)) {
    return static_cast<std::size_t>(std::count_if(depth.begin(), depth.end(), pred));
}
}  // namespace

TEST_F(StorageGLTest, ArrayAtlasAndTexturesGiveTheSameImageWhenSizesMatch) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    // Tolerance: the atlas's shadow matrix has the tile matrix folded in, so a coordinate on a
    // texel boundary may round to its neighbour; and textures' hard test is a linear tap at the
    // texel centre. A handful of edge pixels, each by a full step of the shadow term.
    const test::Tolerance tol{.maxChannelDiff = 2, .maxFailingFraction = 0.002};
    int compared = 0;
    for (View view : {View::Shadow, View::TexelDensity, View::Cascades})
        for (FilterKind filter : {FilterKind::Hard, FilterKind::Pcf2x2, FilterKind::PcfNxN})
            for (Selection selection : {Selection::Interval, Selection::Map}) {
                Settings s = yardAt(view, filter, selection);
                const Rgba8Image reference = test::renderImage(r, s);
                for (CascadeStorage storage : {CascadeStorage::Atlas, CascadeStorage::Textures}) {
                    s.cascades.storage = storage;
                    const Rgba8Image img = test::renderImage(r, s);
                    const test::CompareResult c = test::compareImages(img, reference, tol);
                    EXPECT_TRUE(c.pass) << "storage " << int(storage) << " view " << int(view) << " filter "
                                        << int(filter) << " selection " << int(selection) << ": " << c.summary();
                    ++compared;
                }
            }
    EXPECT_EQ(compared, 36);
}

TEST_F(StorageGLTest, PerCascadeSizesRenderAtTheirStatedResolution) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = test::boxOverPlaneView({0.0f, 12.0f, 14.0f}, {0.0f, 0.0f, 0.0f}, 100.0f);
    s.output = {160, 90, View::Shaded};
    s.cascades.count = 2;
    for (CascadeStorage storage : {CascadeStorage::Atlas, CascadeStorage::Textures}) {
        SCOPED_TRACE(int(storage));
        s.cascades.storage = storage;
        s.cascades.mapSizes = {1024, 1024};
        const FrameStats full = r.render(s);
        const std::size_t coveredFull = coveredShadowTexels(r.shadowMaps())[0];
        s.cascades.mapSizes = {512, 1024};
        const FrameStats half = r.render(s);
        const std::vector<float> depth = readCascadeDepth(r.shadowMaps(), 0);
        EXPECT_EQ(depth.size(), 512u * 512u);  // the readback is the tile, at its own size
        EXPECT_EQ(half.cascades[0].mapSize, 512);
        EXPECT_EQ(half.cascades[1].mapSize, 1024);
        EXPECT_FLOAT_EQ(half.cascades[0].texelWorldSize, 2.0f * full.cascades[0].texelWorldSize);
        EXPECT_FLOAT_EQ(half.cascades[1].texelWorldSize, full.cascades[1].texelWorldSize);
        // The same casters over a quarter of the texels: the map really is 512 a side.
        const std::size_t coveredHalf = countIf(depth, [](float d) { return d < 1.0f; });
        ASSERT_GT(coveredFull, 1000u);
        EXPECT_NEAR(double(coveredHalf) / double(coveredFull), 0.25, 0.02);
        const std::size_t expectedBytes =
            storage == CascadeStorage::Textures ? (512u * 512u + 1024u * 1024u) * 4u
                                                : std::size_t(r.shadowMaps().layout().textures[0].width) *
                                                      std::size_t(r.shadowMaps().layout().textures[0].height) * 4u;
        EXPECT_EQ(half.shadowMapBytes, expectedBytes);
    }
}

TEST_F(StorageGLTest, TheViewerShowsTheAtlasAsOneImageWithTileBorders) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardAt(View::Shaded, FilterKind::Pcf2x2, Selection::Interval);
    s.output = {64, 36, View::Shaded};
    s.cascades.storage = CascadeStorage::Atlas;
    s.cascades.mapSizes = {1024, 512, 512, 256};
    r.render(s);
    ShadowMapView view;
    view.update(r.shadowMaps(), 64);
    ASSERT_NE(view.atlasTexture(), 0u);
    EXPECT_EQ(view.layers(), 4);
    const csm::MapTexture& atlas = r.shadowMaps().layout().textures[0];
    EXPECT_EQ(view.atlasWidth(), 128);
    EXPECT_EQ(view.atlasHeight(), 128 * atlas.height / atlas.width);
    std::vector<std::uint8_t> px(std::size_t(view.atlasWidth()) * std::size_t(view.atlasHeight()) * 4);
    glGetTextureImage(view.atlasTexture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(px.size()), px.data());
    auto at = [&](int x, int y) { return &px[(std::size_t(y) * std::size_t(view.atlasWidth()) + std::size_t(x)) * 4]; };
    // Cascade 0 (1024) is the left half of a 2048 x 1024 atlas: its outline runs down x = 0 and
    // x = 63, and its inside is the depth ramp, not the outline colour.
    EXPECT_EQ(atlas.width, 1536 + 8 * (1536 / 256) + 512);  // padding per smallest side before the last tile
    EXPECT_EQ(atlas.height, 1024);
    const std::uint8_t* edge = at(0, 10);
    EXPECT_EQ(edge[0], 255);
    EXPECT_EQ(edge[1], 217);
    const std::uint8_t* inside = at(30, 30);
    EXPECT_FALSE(inside[0] == 255 && inside[1] == 217);
    s.cascades.storage = CascadeStorage::Textures;
    r.render(s);
    view.update(r.shadowMaps(), 64);
    EXPECT_EQ(view.atlasTexture(), 0u);
}
