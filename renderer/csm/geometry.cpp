#include "renderer/csm/geometry.h"

#include <glm/common.hpp>

namespace st::csm {

bool Aabb::contains(glm::vec3 p, float eps) const {
    return p.x >= min.x - eps && p.y >= min.y - eps && p.z >= min.z - eps &&
           p.x <= max.x + eps && p.y <= max.y + eps && p.z <= max.z + eps;
}

Aabb boundsOf(const Corners& ws) {
    Aabb box{ws[0], ws[0]};
    for (const glm::vec3& p : ws) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

// Seed 003 "Transform AABB": B'min = sum_i min(M_i * min_i, M_i * max_i) + M_3 (column i of the
// matrix times each end of the box along axis i), likewise for max. Exact for affine m because
// each box coordinate appears in only one term of M * p.
Aabb transformAabb(const glm::mat4& m, const Aabb& box) {
    const glm::vec3 translation(m[3]);
    Aabb out{translation, translation};
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 a = glm::vec3(m[i]) * box.min[i];
        const glm::vec3 b = glm::vec3(m[i]) * box.max[i];
        out.min += glm::min(a, b);
        out.max += glm::max(a, b);
    }
    return out;
}

}  // namespace st::csm
