// Cascade storage layouts and the tile matrix (renderer/csm/storage_layout.h).
#include "renderer/csm/cascade_plan.h"
#include "renderer/csm/conventions.h"
#include "renderer/csm/storage_layout.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <stdexcept>
#include <vector>

using namespace st;
using namespace st::csm;

namespace {
CascadeSettings cascades(CascadeStorage storage, std::vector<int> sizes, int padding = 0) {
    CascadeSettings c;
    c.storage = storage;
    c.count = static_cast<int>(sizes.size());
    c.mapSizes = std::move(sizes);
    c.atlasPadding = padding;
    return c;
}

bool overlapOrCloserThan(const MapTile& a, const MapTile& b, int gap) {
    const bool apartX = a.x + a.size + gap <= b.x || b.x + b.size + gap <= a.x;
    const bool apartY = a.y + a.size + gap <= b.y || b.y + b.size + gap <= a.y;
    return !(apartX || apartY);
}
}  // namespace

TEST(StorageLayoutTest, FourEqualTilesMakeSeed003s2x2Atlas) {
    // Seed 003: a 1024 x 1024 atlas of four 512 tiles, split i at (i % 2, i / 2).
    const StorageLayout l = planStorage(cascades(CascadeStorage::Atlas, {512, 512, 512, 512}));
    ASSERT_EQ(l.textures.size(), 1u);
    EXPECT_EQ(l.textures[0], (MapTexture{1024, 1024, 1}));
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(l.tiles[std::size_t(i)], (MapTile{0, 0, (i % 2) * 512, (i / 2) * 512, 512})) << i;
    }
    EXPECT_EQ(storageBytes(l), 1024u * 1024u * 4u);
}

TEST(StorageLayoutTest, PaddingSeparatesEveryPairOfTiles) {
    const StorageLayout l = planStorage(cascades(CascadeStorage::Atlas, {512, 512, 512, 512}, 8));
    EXPECT_EQ(l.textures[0], (MapTexture{1032, 1032, 1}));
    EXPECT_EQ(l.tiles[3], (MapTile{0, 0, 520, 520, 512}));
    EXPECT_EQ(l.padding, 8);
}

TEST(StorageLayoutTest, MixedSizesPackWithoutOverlapAndWithPadding) {
    for (int padding : {0, 4, 16}) {
        const std::vector<int> sizes{2048, 1024, 1024, 512, 256, 256};
        const StorageLayout l = planStorage(cascades(CascadeStorage::Atlas, sizes, padding));
        const MapTexture& t = l.textures[0];
        double tileArea = 0.0;
        for (std::size_t i = 0; i < sizes.size(); ++i) {
            const MapTile& a = l.tiles[i];
            EXPECT_EQ(a.size, sizes[i]);  // input order kept
            EXPECT_GE(a.x, 0);
            EXPECT_GE(a.y, 0);
            EXPECT_LE(a.x + a.size, t.width);
            EXPECT_LE(a.y + a.size, t.height);
            tileArea += double(a.size) * a.size;
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_FALSE(overlapOrCloserThan(a, l.tiles[j], padding)) << i << " vs " << j << ", padding " << padding;
        }
        // 2048 beside a 2048 square holding the rest: 4096 x 2048 (plus padding), not 4096^2.
        EXPECT_EQ(t.height, 2048);
        EXPECT_LE(double(t.width) * t.height, 1.4 * tileArea + 1e6);
    }
}

TEST(StorageLayoutTest, ArrayAndTexturesLayouts) {
    CascadeSettings c;
    c.count = 3;
    c.mapSize = 512;
    const StorageLayout a = planStorage(c);
    EXPECT_EQ(a.textures, (std::vector<MapTexture>{{512, 512, 3}}));
    EXPECT_EQ(a.tiles[2], (MapTile{0, 2, 0, 0, 512}));
    const StorageLayout t = planStorage(cascades(CascadeStorage::Textures, {1024, 512, 256}));
    EXPECT_EQ(t.textures, (std::vector<MapTexture>{{1024, 1024, 1}, {512, 512, 1}, {256, 256, 1}}));
    EXPECT_EQ(t.tiles[1], (MapTile{1, 0, 0, 0, 512}));
    EXPECT_EQ(storageBytes(t), (1024u * 1024u + 512u * 512u + 256u * 256u) * 4u);
}

TEST(StorageLayoutTest, ArrayRefusesDifferentSizesWithTheReason) {
    try {
        (void)planStorage(cascades(CascadeStorage::Array, {1024, 512}));
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("array storage gives every layer one size"), std::string::npos);
    }
    EXPECT_THROW((void)packAtlas(std::vector<int>{1000}, 0), std::invalid_argument);
}

TEST(StorageLayoutTest, TileMatrixMapsTheTileCornersAndKeepsDepth) {
    const MapTexture tex{4096, 2048, 1};
    const MapTile tile{0, 0, 3072, 1024, 512};
    const glm::mat4 m = tileMatrix(tile, tex);
    const glm::vec4 lo = m * glm::vec4(0.0f, 0.0f, 0.25f, 1.0f);
    const glm::vec4 hi = m * glm::vec4(1.0f, 1.0f, 0.75f, 1.0f);
    EXPECT_FLOAT_EQ(lo.x, 3072.0f / 4096.0f);
    EXPECT_FLOAT_EQ(lo.y, 1024.0f / 2048.0f);
    EXPECT_FLOAT_EQ(hi.x, 3584.0f / 4096.0f);
    EXPECT_FLOAT_EQ(hi.y, 1536.0f / 2048.0f);
    EXPECT_FLOAT_EQ(lo.z, 0.25f);
    EXPECT_FLOAT_EQ(hi.z, 0.75f);
    EXPECT_EQ(tileBounds(tile, tex), glm::vec4(lo.x, lo.y, hi.x, hi.y));
}

TEST(StorageLayoutTest, TileMatrixFoldsIntoTheShadowMatrix) {
    // A world point's texel in the tile's own map is the same texel of the atlas, offset by the
    // tile's corner: (tile * ts) * extent = corner + ts_tile * size.
    Settings s;
    s.cascades.storage = CascadeStorage::Atlas;
    s.cascades.count = 3;
    s.cascades.mapSizes = {1024, 512, 256};
    s.cascades.atlasPadding = 4;
    const CascadePlan plan = planCascades(s, 16.0f / 9.0f, Aabb{{-20, 0, -20}, {20, 5, 20}});
    const glm::vec3 ws(1.5f, 0.25f, -3.0f);
    for (int i = 0; i < 3; ++i) {
        const MapTile& tile = plan.storage.tiles[std::size_t(i)];
        const MapTexture& tex = plan.storage.textures[0];
        const glm::vec4 own = clipToTexture() * plan.cascades[std::size_t(i)].viewProj * glm::vec4(ws, 1.0f);
        const glm::vec4 atlas = tileMatrix(tile, tex) * own;
        EXPECT_NEAR(atlas.x * float(tex.width), float(tile.x) + own.x * float(tile.size), 1e-3f);
        EXPECT_NEAR(atlas.y * float(tex.height), float(tile.y) + own.y * float(tile.size), 1e-3f);
        EXPECT_EQ(plan.cascades[std::size_t(i)].mapSize, tile.size);
    }
}

TEST(StorageLayoutTest, TexelWorldSizeDoublesWhenTheMapSizeHalves) {
    Settings s;
    s.cascades.storage = CascadeStorage::Textures;
    s.cascades.count = 2;
    const Aabb bounds{{-20, 0, -20}, {20, 5, 20}};
    s.cascades.mapSizes = {1024, 1024};
    const CascadePlan full = planCascades(s, 1.5f, bounds);
    s.cascades.mapSizes = {1024, 512};
    const CascadePlan half = planCascades(s, 1.5f, bounds);
    EXPECT_FLOAT_EQ(half.cascades[0].texelWorldSize, full.cascades[0].texelWorldSize);
    EXPECT_FLOAT_EQ(half.cascades[1].texelWorldSize, 2.0f * full.cascades[1].texelWorldSize);
}
