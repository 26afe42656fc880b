#pragma once
// Cascade selection on the CPU: exactly the rules of shaders/shadow_sampling.glsl (selectInterval,
// selectMap, edgeMargin), for tests and metrics. tests/metrics/selection_match_gl_test.cpp checks
// that both pick the same cascade for every pixel.
#include "renderer/csm/light_fit.h"
#include "renderer/settings/settings.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace st::csm {

// Interval-based (seed 000/004): the first i with vsDepth <= splits[i+1]. So a depth equal to
// split i+1 belongs to cascade i (the nearer one); a depth below the near split splits[0] gives
// cascade 0 (no lower bound: nothing nearer than the near plane is drawn); a depth above the last
// split, or NaN, gives -1 (beyond the shadow distance: lit). Throws if splits has < 2 values.
int selectCascadeInterval(std::span<const float> splits, float vsDepth);

// The texture-space border map-based selection leaves out so everything the filter reads stays
// inside the tile: filterPaddingTexels(filter) / mapSize (shader edgeMargin()). Past it a pixel
// takes the next map, which holds its whole kernel, rather than filter the map's clamped rim.
float mapEdgeMargin(const FilterSettings& filter, int mapSize);
// The same margin in texels.
float mapEdgeMarginTexels(const FilterSettings& filter);
// How far a PCF kernel's taps reach from the texel a point falls in: taps radius + 1 for NxN
// PCF, 1 (the bilinear footprint) for hard and 2x2.
int filterReachTexels(FilterKind filter, int filterSize);
// Everything the filter reads around a point, texels: the PCF reach above, PCSS's capped radius
// + 1 (blocker search and kernel), or a moment filter's blur radius + 1 (the blur gathered the
// texel's moments from that far). Also the padding filter.padding adds around each light box
// (seed 004, "Padding for PCF Kernels").
int filterPaddingTexels(const FilterSettings& filter);

// Map-based (seed 003/004): the first cascade whose shadow texture coordinates x,y lie inside
// [margin, 1-margin] and z inside [0,1]; -1 if none. Like the shader, each cascade looks at the
// point moved along wsNormal by normalOffsetTexels of its own texel world size (bias.normalOffset),
// so the offset cannot be applied once by the caller.
int selectCascadeMap(std::span<const CascadeFit> cascades, glm::vec3 wsPosition, float margin = 0.0f,
                     glm::vec3 wsNormal = glm::vec3(0.0f), float normalOffsetTexels = 0.0f);

// As the shader does it with cascades.mapSizes: each cascade's margin is marginTexels of its own
// map (marginTexels / fit.mapSize), so a smaller map keeps a wider border of its tile.
int selectCascadeMapPerSize(std::span<const CascadeFit> cascades, glm::vec3 wsPosition, float marginTexels,
                            glm::vec3 wsNormal = glm::vec3(0.0f), float normalOffsetTexels = 0.0f);

}  // namespace st::csm
