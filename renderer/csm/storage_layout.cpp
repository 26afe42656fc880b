#include "renderer/csm/storage_layout.h"

#include "renderer/csm/error_text.h"
#include "renderer/csm/limits.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace st::csm {

int cascadeMapSize(const CascadeSettings& c, int index) {
    const auto i = static_cast<std::size_t>(index);
    return i < c.mapSizes.size() ? c.mapSizes[i] : c.mapSize;
}

namespace {

struct Square {
    int x, y, size;
};

// Takes a free square of side `size` from `free` (first in list order), splitting a larger one
// into its four quadrants in place. With tiles placed largest first every free square is at
// least the current tile's size, so the first one that is big enough always exists while the
// free area covers the tile.
glm::ivec2 takeSquare(std::vector<Square>& free, int size) {
    for (std::size_t i = 0; i < free.size(); ++i) {
        if (free[i].size < size) continue;
        while (free[i].size > size) {
            const Square s = free[i];
            const int h = s.size / 2;
            free[i] = {s.x, s.y, h};
            free.insert(free.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                        {{s.x + h, s.y, h}, {s.x, s.y + h, h}, {s.x + h, s.y + h, h}});
        }
        const glm::ivec2 corner(free[i].x, free[i].y);
        free.erase(free.begin() + static_cast<std::ptrdiff_t>(i));
        return corner;
    }
    throw std::logic_error("atlas packing: no free square of " + str(size) + " texels");
}

}  // namespace

AtlasPacking packAtlas(std::span<const int> sizes, int padding) {
    if (sizes.empty()) fail("atlas packing needs at least one tile");
    if (padding < 0) fail("atlas padding must be >= 0, got " + str(padding));
    for (int s : sizes)
        if (s <= 0 || (s & (s - 1)) != 0) fail("atlas tile sizes must be powers of two, got " + str(s));
    std::vector<std::size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
    const int largest = sizes[order.front()];
    const int smallest = sizes[order.back()];
    double area = 0.0;
    for (int s : sizes) area += double(s) * double(s);
    const int squares = static_cast<int>(std::ceil(area / (double(largest) * double(largest)) - 1e-9));
    const int cols = static_cast<int>(std::ceil(std::sqrt(double(squares)) - 1e-9));
    const int rows = (squares + cols - 1) / cols;
    std::vector<Square> free;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) free.push_back({c * largest, r * largest, largest});
    AtlasPacking out;
    out.offsets.resize(sizes.size());
    for (std::size_t i : order) {
        const glm::ivec2 nominal = takeSquare(free, sizes[i]);
        // Every offset is a multiple of the smallest side; `padding` more texels per smallest side
        // before the tile put at least `padding` texels between tiles that were adjacent.
        const glm::ivec2 corner = nominal + padding * (nominal / smallest);
        out.offsets[i] = corner;
        out.width = std::max(out.width, corner.x + sizes[i]);
        out.height = std::max(out.height, corner.y + sizes[i]);
    }
    return out;
}

StorageLayout planStorage(const CascadeSettings& c) {
    if (c.count < 1) fail("cascades.count must be >= 1, got " + str(c.count));
    std::vector<int> sizes;
    for (int i = 0; i < c.count; ++i) {
        sizes.push_back(cascadeMapSize(c, i));
        if (sizes.back() <= 0) fail("cascade " + str(i) + " map size must be > 0, got " + str(sizes.back()));
    }
    StorageLayout layout;
    layout.storage = c.storage;
    switch (c.storage) {
        case CascadeStorage::Array:
            if (std::any_of(sizes.begin(), sizes.end(), [&](int s) { return s != sizes.front(); }))
                fail("cascades.mapSizes: the array storage gives every layer one size; use storage \"atlas\" or \"textures\"");
            layout.textures.push_back({sizes.front(), sizes.front(), c.count});
            for (int i = 0; i < c.count; ++i) layout.tiles.push_back({0, i, 0, 0, sizes.front()});
            break;
        case CascadeStorage::Atlas: {
            layout.padding = c.atlasPadding;
            const AtlasPacking packing = packAtlas(sizes, c.atlasPadding);
            layout.textures.push_back({packing.width, packing.height, 1});
            for (std::size_t i = 0; i < sizes.size(); ++i)
                layout.tiles.push_back({0, 0, packing.offsets[i].x, packing.offsets[i].y, sizes[i]});
            break;
        }
        case CascadeStorage::Textures:
            for (int i = 0; i < c.count; ++i) {
                const int s = sizes[static_cast<std::size_t>(i)];
                layout.textures.push_back({s, s, 1});
                layout.tiles.push_back({i, 0, 0, 0, s});
            }
            break;
    }
    return layout;
}

glm::mat4 tileMatrix(const MapTile& tile, const MapTexture& texture) {
    glm::mat4 m(1.0f);
    m[0][0] = float(tile.size) / float(texture.width);
    m[1][1] = float(tile.size) / float(texture.height);
    m[3] = glm::vec4(float(tile.x) / float(texture.width), float(tile.y) / float(texture.height), 0.0f, 1.0f);
    return m;
}

glm::vec4 tileBounds(const MapTile& tile, const MapTexture& texture) {
    const float w = float(texture.width);
    const float h = float(texture.height);
    return {float(tile.x) / w, float(tile.y) / h, float(tile.x + tile.size) / w, float(tile.y + tile.size) / h};
}

std::size_t storageBytes(const StorageLayout& layout) {
    std::size_t bytes = 0;
    for (const MapTexture& t : layout.textures)
        bytes += std::size_t(t.width) * std::size_t(t.height) * std::size_t(t.layers) * kShadowTexelBytes;
    return bytes;
}

}  // namespace st::csm
