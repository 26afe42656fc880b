#pragma once
// Small value types for the cascade math. GLM only.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace st::csm {

struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }
    bool contains(glm::vec3 p, float eps = 0.0f) const;
};

// Eight corners of a frustum slice in world space. Order: near plane then far plane, each as
// (-x,-y), (+x,-y), (+x,+y), (-x,+y) in view space.
using Corners = std::array<glm::vec3, 8>;

Aabb boundsOf(const Corners& ws);
// Seed 003 ("Transform AABB"): the AABB of a transformed AABB from the matrix's absolute
// values, without transforming the eight corners. Affine m only.
Aabb transformAabb(const glm::mat4& m, const Aabb& box);

}  // namespace st::csm
