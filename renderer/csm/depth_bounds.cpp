#include "renderer/csm/depth_bounds.h"

#include <algorithm>

namespace st::csm {

SplitRange fittedSplitRange(float nearPlane, float end, const std::optional<DepthRange>& seen) {
    if (!seen || !(seen->vsMin < end) || !(seen->vsMax >= seen->vsMin)) return {nearPlane, end};
    constexpr float kPad = 1e-4f;      // relative: covers the depth buffer's float round trip
    constexpr float kMinLength = 1e-3f;  // relative to the start
    float b = std::clamp(seen->vsMin * (1.0f - kPad), nearPlane, end);
    float e = std::clamp(seen->vsMax * (1.0f + kPad), nearPlane, end);
    if (e - b < kMinLength * b) {
        e = std::min(end, b + kMinLength * b);
        b = std::max(nearPlane, std::min(b, e - kMinLength * e));
    }
    return {b, e};
}

}  // namespace st::csm
