#include "renderer/csm/selection.h"

#include "renderer/csm/conventions.h"

#include <glm/vec4.hpp>

#include <stdexcept>
#include <string>

namespace st::csm {

int selectCascadeInterval(std::span<const float> splits, float vsDepth) {
    if (splits.size() < 2)
        throw std::invalid_argument("splits must hold at least 2 values, got " +
                                    std::to_string(splits.size()));
    // Closed interval [z_0, z_N]; NaN depths fail both comparisons and count as outside.
    if (!(vsDepth >= splits.front() && vsDepth <= splits.back())) return -1;
    const int count = static_cast<int>(splits.size()) - 1;
    for (int i = 0; i < count - 1; ++i)
        if (vsDepth < splits[static_cast<std::size_t>(i) + 1]) return i;
    return count - 1;  // includes vsDepth == z_N
}

int selectCascadeMap(std::span<const CascadeFit> cascades, glm::vec3 wsPosition, float margin) {
    const glm::mat4 tsFromCs = clipToTexture();
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        // Orthographic: w stays 1, no divide (seed 000).
        const glm::vec4 ts = tsFromCs * cascades[i].viewProj * glm::vec4(wsPosition, 1.0f);
        const bool inXY = ts.x >= margin && ts.x <= 1.0f - margin && ts.y >= margin &&
                          ts.y <= 1.0f - margin;
        if (inXY && ts.z >= 0.0f && ts.z <= 1.0f) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace st::csm
