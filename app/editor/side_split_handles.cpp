#include "app/editor/side_split_handles.h"

#include <glm/glm.hpp>

namespace st::app {
namespace {

// World point to the picture's uv (top left origin: the panel shows the picture with v flipped
// so its top row is up, as clip-space +y); nullopt-like {-1, -1} behind the camera.
ImVec2 pictureUv(const glm::mat4& viewProj, glm::vec3 ws) {
    const glm::vec4 cs = viewProj * glm::vec4(ws, 1.0f);
    if (cs.w <= 1e-6f) return {-1.0f, -1.0f};
    return {0.5f + 0.5f * cs.x / cs.w, 0.5f - 0.5f * cs.y / cs.w};
}

}  // namespace

std::vector<ui::SideSplitHandle> sideSplitHandles(const csm::CascadePlan& plan, const OrbitCamera& orbit, float aspect) {
    std::vector<ui::SideSplitHandle> handles;
    if (plan.splits.size() < 3) return handles;
    const csm::CameraParams side = sideCamera(plan, orbit, aspect);
    const glm::mat4 viewProj = csm::projectionMatrix(side) * csm::viewMatrix(side);
    const glm::vec3 eye = plan.camera.wsPosition;
    const glm::vec3 forward = glm::normalize(plan.camera.wsTarget - plan.camera.wsPosition);
    for (std::size_t i = 1; i + 1 < plan.splits.size(); ++i) {
        const float depth = plan.splits[i];
        const float step = std::max(depth * 0.01f, 0.01f);  // metres: the derivative by a small difference
        const ImVec2 at = pictureUv(viewProj, eye + forward * depth);
        const ImVec2 next = pictureUv(viewProj, eye + forward * (depth + step));
        handles.push_back({at, {(next.x - at.x) / step, (next.y - at.y) / step}});
    }
    return handles;
}

}  // namespace st::app
