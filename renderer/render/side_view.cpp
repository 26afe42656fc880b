#include "renderer/render/side_view.h"

#include "renderer/csm/frustum.h"
#include "renderer/render/cascade_tints.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>

namespace st {
namespace {
void addEdges(std::vector<LineVertex>& out, const csm::Corners& c, glm::vec3 color, bool sides) {
    for (int i = 0; i < 4; ++i) {
        int j = (i + 1) % 4;
        out.push_back({c[i], color}), out.push_back({c[j], color});          // near rectangle
        out.push_back({c[4 + i], color}), out.push_back({c[4 + j], color});  // far rectangle
        if (sides) out.push_back({c[i], color}), out.push_back({c[4 + i], color});
    }
}

csm::Corners boxCorners(const csm::CascadeFit& f) {
    glm::mat4 wsFromLs = glm::inverse(f.lsView);
    const csm::Aabb& b = f.lsBox;
    csm::Corners c;
    // Near face (toward the sun, max z) first, then the far face, matching the slice order.
    const float zs[2] = {b.max.z, b.min.z};
    for (int k = 0; k < 2; ++k) {
        const glm::vec2 xy[4] = {{b.min.x, b.min.y}, {b.max.x, b.min.y}, {b.max.x, b.max.y}, {b.min.x, b.max.y}};
        for (int i = 0; i < 4; ++i) c[k * 4 + i] = glm::vec3(wsFromLs * glm::vec4(xy[i], zs[k], 1.0f));
    }
    return c;
}
}  // namespace

glm::vec3 cascadeTint(int cascade) {
    const LinearRgb t = cascadeTintOf(cascade);
    return {t.r, t.g, t.b};
}

csm::CameraParams sideCamera(const csm::CascadePlan& plan, const OrbitCamera& orbit, float aspect) {
    // Centre and size of what the shadows cover: the frustum up to the last split.
    csm::Corners all = csm::sliceCornersFromCamera(plan.camera, plan.splits.front(), plan.splits.back());
    glm::vec3 centre(0.0f);
    for (glm::vec3 p : all) centre += p / 8.0f;
    float radius = 0.0f;
    for (glm::vec3 p : all) radius = std::max(radius, glm::length(p - centre));
    float yaw = glm::radians(orbit.yawDeg), pitch = glm::radians(std::clamp(orbit.pitchDeg, -89.0f, 89.0f));
    glm::vec3 dir(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    csm::CameraParams c;
    c.wsTarget = centre + orbit.panOffset;
    float distance = 2.2f * radius * std::max(orbit.zoom, 0.05f);
    c.wsPosition = c.wsTarget + dir * distance;
    c.fovY = glm::radians(45.0f);
    c.aspect = aspect;
    c.nearPlane = std::max(0.05f, distance * 0.01f);
    c.farPlane = distance * 4.0f + 4.0f * radius;
    return c;
}

std::vector<LineVertex> cascadeWireframes(const csm::CascadePlan& plan) {
    std::vector<LineVertex> lines;
    int n = static_cast<int>(plan.cascades.size());
    addEdges(lines, csm::sliceCornersFromCamera(plan.camera, plan.splits.front(), plan.splits.back()),
             glm::vec3(1.0f), true);
    for (int i = 0; i < n; ++i) {
        // The split plane at the far end of cascade i, in its tint; the last one is the frustum's
        // far face, which stays white so the frustum has a colour no cascade uses.
        csm::Corners far = csm::sliceCornersFromCamera(plan.camera, plan.splits[i], plan.splits[i + 1]);
        if (i + 1 < n)
            for (int k = 0; k < 4; ++k) lines.push_back({far[4 + k], cascadeTint(i)}), lines.push_back({far[4 + (k + 1) % 4], cascadeTint(i)});
        addEdges(lines, boxCorners(plan.cascades[i]), cascadeTint(i), true);
    }
    return lines;
}

}  // namespace st
