#include "renderer/csm/selection.h"

#include "renderer/csm/conventions.h"
#include "renderer/csm/error_text.h"

#include <glm/vec4.hpp>

#include <cmath>

namespace st::csm {

int selectCascadeInterval(std::span<const float> splits, float vsDepth) {
    if (splits.size() < 2) fail("splits must hold at least 2 values, got " + str(splits.size()));
    const int count = static_cast<int>(splits.size()) - 1;
    for (int i = 0; i < count; ++i)
        if (vsDepth <= splits[static_cast<std::size_t>(i) + 1]) return i;
    return -1;
}

int filterReachTexels(FilterKind filter, int filterSize) {
    return filter == FilterKind::PcfNxN || filter == FilterKind::Tent ? filterSize / 2 + 1 : 1;
}

int filterPaddingTexels(const FilterSettings& f) {
    if (f.kind == FilterKind::Pcss) return static_cast<int>(std::ceil(f.pcssMaxRadius)) + 1;
    if (f.kind == FilterKind::Vogel) return static_cast<int>(std::ceil(f.radius)) + 1;
    if (isMomentFilter(f.kind)) return f.blurRadius + 1;
    return filterReachTexels(f.kind, f.size);
}

float mapEdgeMarginTexels(const FilterSettings& filter) { return float(filterPaddingTexels(filter)); }

float mapEdgeMargin(const FilterSettings& filter, int mapSize) { return mapEdgeMarginTexels(filter) / float(mapSize); }

namespace {
// The first cascade i with its coordinates inside [margin(i), 1 - margin(i)] in x, y and [0, 1] in z.
template <class Margin>
int firstMapHolding(std::span<const CascadeFit> cascades, glm::vec3 wsPosition, Margin marginOf, glm::vec3 wsNormal,
                    float normalOffsetTexels) {
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        const float margin = marginOf(cascades[i]);
        // The shader's uShadowMatrix is this product, formed on the CPU before the multiply;
        // orthographic, so w stays 1 and there is no divide (seed 000).
        const glm::mat4 tsFromWs = clipToTexture() * cascades[i].viewProj;
        const glm::vec3 p = wsPosition + wsNormal * (normalOffsetTexels * cascades[i].texelWorldSize);
        const glm::vec4 ts = tsFromWs * glm::vec4(p, 1.0f);
        const bool inXY = ts.x >= margin && ts.x <= 1.0f - margin && ts.y >= margin && ts.y <= 1.0f - margin;
        if (inXY && ts.z >= 0.0f && ts.z <= 1.0f) return static_cast<int>(i);
    }
    return -1;
}
}  // namespace

int selectCascadeMap(std::span<const CascadeFit> cascades, glm::vec3 wsPosition, float margin, glm::vec3 wsNormal,
                     float normalOffsetTexels) {
    return firstMapHolding(cascades, wsPosition, [margin](const CascadeFit&) { return margin; }, wsNormal,
                           normalOffsetTexels);
}

int selectCascadeMapPerSize(std::span<const CascadeFit> cascades, glm::vec3 wsPosition, float marginTexels,
                            glm::vec3 wsNormal, float normalOffsetTexels) {
    return firstMapHolding(
        cascades, wsPosition, [marginTexels](const CascadeFit& f) { return marginTexels / float(f.mapSize); },
        wsNormal, normalOffsetTexels);
}

}  // namespace st::csm
