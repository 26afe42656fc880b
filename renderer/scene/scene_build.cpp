// Helpers that build procedural geometry into a Scene (flat-shaded boxes and quads).
#include "renderer/scene/scene.h"

#include <glm/common.hpp>

#include <algorithm>
#include <limits>

namespace st {
namespace {
void addQuad(Scene& s, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
    auto base = static_cast<std::uint32_t>(s.vertices.size());
    for (glm::vec3 p : {a, b, c, d}) s.vertices.push_back({p, n, glm::vec2(p.x, p.z)});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) s.indices.push_back(base + i);
}

void beginItem(Scene& s, int material) {
    DrawItem item;
    item.firstIndex = static_cast<std::uint32_t>(s.indices.size());
    item.material = material;
    s.draws.push_back(item);
}

void endItem(Scene& s) {
    DrawItem& item = s.draws.back();
    item.indexCount = static_cast<std::uint32_t>(s.indices.size()) - item.firstIndex;
}
}  // namespace

void addBox(Scene& s, glm::vec3 lo, glm::vec3 hi, int material) {
    beginItem(s, material);
    // Counter-clockwise seen from outside.
    addQuad(s, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, {0, 0, 1});
    addQuad(s, {hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {0, 0, -1});
    addQuad(s, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {1, 0, 0});
    addQuad(s, {lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}, {-1, 0, 0});
    addQuad(s, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}, {0, 1, 0});
    addQuad(s, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}, {0, -1, 0});
    endItem(s);
}

void addGroundQuad(Scene& s, float h, float y, int material) {
    beginItem(s, material);
    addQuad(s, {-h, y, h}, {h, y, h}, {h, y, -h}, {-h, y, -h}, {0, 1, 0});
    endItem(s);
}

void finalizeBounds(Scene& s) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    s.wsBounds = {glm::vec3(inf), glm::vec3(-inf)};
    for (DrawItem& d : s.draws) {
        d.wsBounds = {glm::vec3(inf), glm::vec3(-inf)};
        for (std::uint32_t i = d.firstIndex; i < d.firstIndex + d.indexCount; ++i) {
            glm::vec3 p = s.vertices[s.indices[i]].position;
            d.wsBounds.min = glm::min(d.wsBounds.min, p);
            d.wsBounds.max = glm::max(d.wsBounds.max, p);
        }
        s.wsBounds.min = glm::min(s.wsBounds.min, d.wsBounds.min);
        s.wsBounds.max = glm::max(s.wsBounds.max, d.wsBounds.max);
    }
    // An empty scene still needs finite bounds for the light-box math: a unit box at the origin.
    if (s.draws.empty() || s.indices.empty()) s.wsBounds = {glm::vec3(-0.5f), glm::vec3(0.5f)};
}

}  // namespace st
