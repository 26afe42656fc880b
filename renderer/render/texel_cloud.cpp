#include "renderer/render/texel_cloud.h"

#include "renderer/render/shadow_maps.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace st {

void backProjectTexels(const std::vector<float>& depth, const TileTexels& tile, const glm::mat4& shadowMatrix,
                       int stride, glm::vec3 colour, const std::function<bool(glm::vec3)>& keep,
                       std::vector<LineVertex>& out) {
    const glm::mat4 wsFromTs = glm::inverse(shadowMatrix);
    for (int y = 0; y < tile.size; y += stride)
        for (int x = 0; x < tile.size; x += stride) {
            const float d = depth[std::size_t(y) * std::size_t(tile.size) + std::size_t(x)];
            if (!(d < 1.0f)) continue;  // cleared: no caster in this texel
            const glm::vec4 ts((float(tile.tileX + x) + 0.5f) / float(tile.textureWidth),
                               (float(tile.tileY + y) + 0.5f) / float(tile.textureHeight), d, 1.0f);
            const glm::vec4 ws = wsFromTs * ts;
            const glm::vec3 p = glm::vec3(ws) / ws.w;
            if (keep(p)) out.push_back({p, colour});
        }
}

namespace {
bool inTile(const csm::CascadePlan& plan, const glm::mat4& shadowMatrix, int cascade, glm::vec3 ws) {
    const csm::MapTile& tile = plan.storage.tiles[static_cast<std::size_t>(cascade)];
    const glm::vec4 b = csm::tileBounds(tile, plan.storage.textures[static_cast<std::size_t>(tile.texture)]);
    const glm::vec3 ts = glm::vec3(shadowMatrix * glm::vec4(ws, 1.0f));
    return ts.x >= b.x && ts.x <= b.z && ts.y >= b.y && ts.y <= b.w && ts.z >= 0.0f && ts.z <= 1.0f;
}
}  // namespace

bool shadedByCascade(const csm::CascadePlan& plan, Selection selection, const std::vector<glm::mat4>& shadowMatrices,
                     int cascade, glm::vec3 ws) {
    const glm::vec4 cs = plan.csProj * plan.vsView * glm::vec4(ws, 1.0f);
    if (cs.w <= 0.0f || std::abs(cs.x) > cs.w || std::abs(cs.y) > cs.w) return false;
    const float depth = -(plan.vsView * glm::vec4(ws, 1.0f)).z;  // view depth: the camera looks down -z
    if (depth < plan.splits.front() || depth > plan.splits.back()) return false;
    if (selection == Selection::Map) {
        for (int j = 0; j < cascade; ++j)
            if (inTile(plan, shadowMatrices[static_cast<std::size_t>(j)], j, ws)) return false;
        return inTile(plan, shadowMatrices[static_cast<std::size_t>(cascade)], cascade, ws);
    }
    const std::size_t i = static_cast<std::size_t>(cascade);
    return depth >= plan.splits[i] && depth <= plan.splits[i + 1];
}

int texelCloudStride(int mapSize) {
    const double perSide = std::sqrt(double(kTexelCloudPointsPerCascade));
    return std::max(1, int(std::ceil(double(mapSize) / perSide)));
}

std::vector<LineVertex> texelCloud(const ShadowMaps& maps, const csm::CascadePlan& plan, Selection selection,
                                   const std::vector<glm::mat4>& shadowMatrices) {
    std::vector<LineVertex> points;
    for (int i = 0; i < maps.cascades() && i < int(shadowMatrices.size()); ++i) {
        const csm::MapTile& tile = maps.tile(i);
        const csm::MapTexture& texture = maps.layout().textures[std::size_t(tile.texture)];
        const TileTexels t{tile.x, tile.y, tile.size, texture.width, texture.height};
        const auto shaded = [&](glm::vec3 p) { return shadedByCascade(plan, selection, shadowMatrices, i, p); };
        backProjectTexels(readCascadeDepth(maps, i), t, shadowMatrices[std::size_t(i)], texelCloudStride(tile.size),
                          cascadeTint(i), shaded, points);
    }
    return points;
}

}  // namespace st
