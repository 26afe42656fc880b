#include "app/editor/view_actions.h"

#include "app/editor/fly_camera.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace st::app {

std::string frameKeepingClipPlanes(CameraSettings& cam, const csm::Aabb& b) {
    CameraSettings framed = cam;
    frameBounds(framed, b);
    cam.position = framed.position;
    cam.target = framed.target;
    const float reach = glm::length(b.center() - cam.position) + 0.5f * glm::length(b.extent());
    if (reach <= cam.farPlane) return {};
    // Too far to show whole: come in to half the far plane, so at least the middle is on screen.
    const glm::vec3 forward = glm::normalize(cam.target - cam.position);
    const float distance = std::min(glm::length(cam.target - cam.position), 0.5f * cam.farPlane);
    cam.position = cam.target - forward * distance;
    char text[200];
    std::snprintf(text, sizeof text, "the scene reaches %.0f m, past the far plane (%.0f m): raise Camera > Far plane to see all of it",
                  std::ceil(reach), cam.farPlane);
    return text;
}

csm::Aabb framingBounds(const std::vector<csm::Aabb>& items, const csm::Aabb& whole) {
    if (items.size() < 3) return whole;
    std::vector<float> diagonals;
    for (const csm::Aabb& b : items) diagonals.push_back(glm::length(b.extent()));
    std::vector<float> sorted = diagonals;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    const float limit = 20.0f * std::max(sorted[sorted.size() / 2], 1e-3f);
    csm::Aabb kept{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(-std::numeric_limits<float>::max())};
    std::size_t sprawling = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (diagonals[i] > limit) {
            ++sprawling;
            continue;
        }
        kept.min = glm::min(kept.min, items[i].min);
        kept.max = glm::max(kept.max, items[i].max);
    }
    if (sprawling == 0 || 2 * sprawling >= items.size()) return whole;
    return kept;
}

std::optional<CameraSettings> CameraGesture::update(const CameraSettings& before, const CameraSettings& after, bool held) {
    if (!start_ && before != after) start_ = before;
    if (held || !start_) return std::nullopt;
    std::optional<CameraSettings> ended = std::move(start_);
    start_.reset();
    return ended;
}

}  // namespace st::app
