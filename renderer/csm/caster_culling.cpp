#include "renderer/csm/caster_culling.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace st::csm {

std::array<float, 2> receiverDepthRange(const Settings& s, std::span<const float> splits, int index,
                                        const CascadeFit& fit) {
    if (s.cascades.selection == Selection::Map) return {splits.front(), splits.back()};
    float a = fit.vsNear;
    if (s.cascades.blendBand > 0.0f && index > 0) a = std::min(a, splits[std::size_t(index) - 1]);
    return {a, fit.vsFar};
}

CasterVolume casterVolume(const Settings& s, const CameraParams& cam, std::span<const float> splits,
                          int index, const CascadeFit& fit) {
    CasterVolume v;
    v.lsView = fit.lsView;
    v.lsBox = fit.lsBox;
    v.pancake = s.cascades.zExtension == ZExtension::Pancake;
    v.sweep = s.cascades.casterCulling;
    if (!v.sweep) return v;
    const auto [a, b] = receiverDepthRange(s, splits, index, fit);
    Corners c = sliceCornersFromCamera(cam, a, b);
    std::vector<glm::vec2> xy;
    v.lsReceiverMinZ = INFINITY;
    for (const glm::vec3& p : c) {
        const glm::vec3 ls(fit.lsView * glm::vec4(p, 1.0f));
        xy.emplace_back(ls.x, ls.y);
        v.lsReceiverMinZ = std::min(v.lsReceiverMinZ, ls.z);
    }
    v.lsHull = convexHull(std::move(xy));
    // How far off the receiver's own x,y a pixel's taps reach (shadow_sampling.glsl): the NxN
    // kernel's radius, one texel of the 2x2 comparison, the normal offset; plus one texel spare
    // for float rounding. The texel is the map's: fit.texelWorldSize.
    const float taps = s.filter.kind == FilterKind::PcfNxN || s.filter.kind == FilterKind::Tent ? float(s.filter.size / 2)
                       : s.filter.kind == FilterKind::Vogel ? std::ceil(s.filter.radius)
                                                            : 0.0f;
    const float offset = cascadeBiasMetres(s.bias, index, fit.texelWorldSize, fit.lsBox.max.z - fit.lsBox.min.z).receiverOffset /
                         std::max(fit.texelWorldSize, 1e-9f);  // in texels
    v.margin = fit.texelWorldSize * (taps + 2.0f + offset);
    v.lsReceiverMinZ -= fit.texelWorldSize * (offset + 1.0f);  // normal offset moves receivers in z too
    return v;
}

bool lsBoundsMeetBox(const Aabb& ls, const Aabb& box, bool pancake) {
    const bool overlapXY = ls.max.x >= box.min.x && ls.min.x <= box.max.x && ls.max.y >= box.min.y &&
                           ls.min.y <= box.max.y;
    const bool behind = ls.max.z < box.min.z;  // +Z points toward the sun
    const bool inFront = ls.min.z > box.max.z && !pancake;
    return overlapXY && !behind && !inFront;
}

bool casterMayShadow(const Aabb& wsBounds, const CasterVolume& v) {
    const Aabb ls = transformAabb(v.lsView, wsBounds);
    if (!lsBoundsMeetBox(ls, v.lsBox, v.pancake)) return false;
    if (!v.sweep) return true;
    if (ls.max.z < v.lsReceiverMinZ) return false;  // behind every receiver
    // Separating axes of the rectangle ls.xy and the hull: the hull's edge normals (the
    // rectangle's own axes are covered by the box test above, the box holds the hull).
    const std::size_t n = v.lsHull.size();
    if (n < 3) return true;  // degenerate footprint: keep what the box keeps
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 p = v.lsHull[i];
        const glm::vec2 e = v.lsHull[(i + 1) % n] - p;
        const glm::vec2 outward = glm::normalize(glm::vec2(e.y, -e.x));  // right of a CCW edge
        float hullMax = -INFINITY;
        for (const glm::vec2& q : v.lsHull) hullMax = std::max(hullMax, glm::dot(outward, q));
        // The rectangle's nearest point along the outward normal.
        const float rectMin = std::min(outward.x * ls.min.x, outward.x * ls.max.x) +
                              std::min(outward.y * ls.min.y, outward.y * ls.max.y);
        if (rectMin > hullMax + v.margin) return false;
    }
    return true;
}

std::vector<glm::vec2> convexHull(std::vector<glm::vec2> pts) {
    std::sort(pts.begin(), pts.end(), [](glm::vec2 a, glm::vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return pts;
    auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::vec2> h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {  // lower hull
        while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0.0f) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {  // upper hull
        while (k >= t && cross(h[k - 2], h[k - 1], pts[i - 1]) <= 0.0f) --k;
        h[k++] = pts[i - 1];
    }
    h.resize(k - 1);
    return h;
}

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& m) {
    // Rows of the matrix (GLM is column-major: m[col][row]).
    auto row = [&](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    const glm::vec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
}

bool aabbInFrustum(const Aabb& b, const std::array<glm::vec4, 6>& planes) {
    for (const glm::vec4& pl : planes) {
        // The box corner farthest along the plane's normal.
        const glm::vec3 p(pl.x >= 0.0f ? b.max.x : b.min.x, pl.y >= 0.0f ? b.max.y : b.min.y,
                          pl.z >= 0.0f ? b.max.z : b.min.z);
        if (glm::dot(glm::vec3(pl), p) + pl.w < 0.0f) return false;
    }
    return true;
}

}  // namespace st::csm
