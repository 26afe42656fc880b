#include "tune/tune_views.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>

namespace st::tune {
namespace {

std::string orbitName(double yawDeg, double rise) {
    char text[64];
    std::snprintf(text, sizeof text, "orbit %+.0f deg, %s %.0f %%", yawDeg, rise >= 0 ? "up" : "down", std::abs(rise) * 100.0);
    return text;
}

// The camera turned about the vertical through its target and raised by `rise` of its offset.
CameraSettings orbit(const CameraSettings& c, double yawDeg, double rise) {
    CameraSettings out = c;
    const glm::vec3 offset = c.position - c.target;
    const float a = float(glm::radians(yawDeg));
    glm::vec3 turned{offset.x * std::cos(a) - offset.z * std::sin(a), offset.y, offset.x * std::sin(a) + offset.z * std::cos(a)};
    const float horizontal = glm::length(glm::vec2(offset.x, offset.z));
    turned.y += float(rise) * std::max(std::abs(offset.y), 0.25f * horizontal);
    out.position = c.target + turned;
    return out;
}

}  // namespace

std::vector<View> tuneViews(const Settings& s, int count, int holdOutEvery) {
    std::vector<View> views{{"preset camera", s.camera, false}};
    for (const CameraKeyframe& k : s.path.keyframes) {
        if (int(views.size()) >= count) break;
        CameraSettings c = s.camera;
        c.position = k.position;
        c.target = k.target;
        c.fovY = k.fovY;
        views.push_back({"path pose " + std::to_string(views.size()), c, false});
    }
    for (int i = 1; int(views.size()) < count; ++i) {
        const double yaw = 12.0 * ((i + 1) / 2) * (i % 2 ? 1.0 : -1.0);
        const double rise = (i % 4 == 1 || i % 4 == 2) ? 0.15 : -0.15;
        views.push_back({orbitName(yaw, rise), orbit(s.camera, yaw, rise), false});
    }
    if (holdOutEvery > 0)
        for (std::size_t i = 1; i < views.size(); ++i) views[i].heldOut = (i + 1) % std::size_t(holdOutEvery) == 0;
    return views;
}

Settings onView(Settings s, const View& v) {
    s.camera = v.camera;
    s.path = {};
    return s;
}

}  // namespace st::tune
