#pragma once
// Seed 003's view of how a shadow map "sees" the scene: every texel that holds a caster, back-
// projected through its cascade's shadow matrix to the world point it stores, drawn as a point in
// the cascade's tint over the side view (output.sideTexels; LinePass::drawPoints draws them). The
// unprojection is pure math, tested without a context.
#include "renderer/csm/cascade_plan.h"
#include "renderer/render/side_view.h"

#include <glm/mat4x4.hpp>

#include <functional>
#include <vector>

namespace st {

class ShadowMaps;

// Texels of one tile, every `stride`-th in x and y, rows from the bottom as readCascadeDepth
// gives them: the world point of each texel centre whose depth is below the clear value 1.
// `shadowMatrix` maps ws to the texture's uv and depth (the tile matrix folded in), as the shaders.
struct TileTexels {
    int tileX = 0, tileY = 0, size = 0;  // the tile inside its texture, texels
    int textureWidth = 0, textureHeight = 0;
};
// Only points `keep` accepts are written.
void backProjectTexels(const std::vector<float>& depth, const TileTexels& tile, const glm::mat4& shadowMatrix,
                       int stride, glm::vec3 colour, const std::function<bool(glm::vec3)>& keep,
                       std::vector<LineVertex>& out);

// Whether cascade i shades a world point: inside the camera's frustum, and inside its slice
// (interval selection) or the first map whose tile holds the point (map selection, without the
// shader's filter margin). Drawing only those texels keeps the nested maps apart, each over the
// part of the scene it serves, at its own density.
bool shadedByCascade(const csm::CascadePlan& plan, Selection selection, const std::vector<glm::mat4>& shadowMatrices,
                     int cascade, glm::vec3 ws);

// At most about this many points per cascade: the stride grows with the map so the view stays
// interactive on big maps (each point still sits on a real texel).
inline constexpr int kTexelCloudPointsPerCascade = 1 << 17;
int texelCloudStride(int mapSize);

// Every cascade's texels that it shades (shadedByCascade), read back from the maps: the cost of
// this debug view, paid only when the side view is re-rendered with output.sideTexels.
std::vector<LineVertex> texelCloud(const ShadowMaps& maps, const csm::CascadePlan& plan, Selection selection,
                                   const std::vector<glm::mat4>& shadowMatrices);

}  // namespace st
