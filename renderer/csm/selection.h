#pragma once
// Cascade selection on the CPU: the same rules the main-pass shader applies, for tests/metrics.
#include "renderer/csm/light_fit.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace st::csm {

// Interval-based (seed 000/004): the first i with vsDepth < splits[i+1]; -1 if vsDepth is
// outside [splits[0], splits[N]] (beyond the shadow distance: lit).
int selectCascadeInterval(std::span<const float> splits, float vsDepth);

// Map-based (seed 003/004): the first cascade whose shadow texture coordinates x,y lie inside
// [margin, 1-margin] and z inside [0,1]; -1 if none.
int selectCascadeMap(std::span<const CascadeFit> cascades, glm::vec3 wsPosition,
                     float margin = 0.0f);

}  // namespace st::csm
