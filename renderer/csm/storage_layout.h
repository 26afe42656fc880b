#pragma once
// Where each cascade's depth map lives (cascades.storage): a layer of one array, a tile of one
// atlas (seed 003) or its own texture (seed 002), and the tile matrix that folds a tile's place
// into the cascade's shadow matrix. Pure math: the renderer allocates what this describes.
#include "renderer/settings/settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace st::csm {

// Texels per side of cascade `index`'s map: cascades.mapSizes[index] when the list is given, else
// cascades.mapSize.
int cascadeMapSize(const CascadeSettings& c, int index);

// One depth texture: a D32F 2D array (the atlas and each per-cascade texture have one layer).
struct MapTexture {
    int width = 0;
    int height = 0;
    int layers = 0;
    bool operator==(const MapTexture&) const = default;
};

// Cascade i's map inside its texture: texels [x, x + size) x [y, y + size) of `layer`.
struct MapTile {
    int texture = 0;  // index into StorageLayout::textures
    int layer = 0;
    int x = 0;
    int y = 0;
    int size = 0;  // texels per side
    bool operator==(const MapTile&) const = default;
};

struct StorageLayout {
    CascadeStorage storage = CascadeStorage::Array;
    int padding = 0;  // atlas: at least this many texels between any two tiles
    std::vector<MapTexture> textures;
    std::vector<MapTile> tiles;  // one per cascade
};

// The layout of cascades.count maps. Throws std::invalid_argument when the array storage is given
// different sizes (a texture array has one size for every layer) or a size is not positive.
StorageLayout planStorage(const CascadeSettings& c);

// Atlas packing of square tiles whose sides are powers of two: largest first, each into the
// first free square of a quadtree over a near-square grid of squares of the largest side (the 2x2
// atlas of seed 003 for four equal tiles), then spread so that any two tiles are at least
// `padding` texels apart. Returns the offsets in input order and the atlas extent.
struct AtlasPacking {
    std::vector<glm::ivec2> offsets;
    int width = 0;
    int height = 0;
};
AtlasPacking packAtlas(std::span<const int> sizes, int padding);

// Maps the tile's own texture coordinates ([0,1]^2, z untouched) to its texture's: scale
// size / extent, offset tile corner / extent (seed 003's tile matrix, without its y flip: GL's
// viewport and texture rows both start at the bottom). An affine matrix, so it folds into the
// orthographic shadow matrix exactly: shadowMatrix = tileMatrix * clipToTexture * viewProj.
glm::mat4 tileMatrix(const MapTile& tile, const MapTexture& texture);

// The tile in its texture's uv: (x0, y0, x1, y1).
glm::vec4 tileBounds(const MapTile& tile, const MapTexture& texture);

// Bytes of every texture of the layout (D32F texels, csm::kShadowTexelBytes each).
std::size_t storageBytes(const StorageLayout& layout);

}  // namespace st::csm
