#include "app/editor/fly_camera.h"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace st::app {
namespace {
constexpr float kRadiansPerPixel = 0.004f;

glm::vec3 forwardOf(const CameraSettings& c) {
    glm::vec3 d = c.target - c.position;
    float len = glm::length(d);
    return len > 1e-6f ? d / len : glm::vec3(0.0f, 0.0f, -1.0f);
}

// Yaw about world up, pitch about the camera's right axis, kept short of straight up/down.
glm::vec3 rotate(glm::vec3 fwd, glm::vec2 delta) {
    float yaw = std::atan2(fwd.x, -fwd.z) + delta.x * kRadiansPerPixel;
    float pitch = std::asin(std::clamp(fwd.y, -1.0f, 1.0f)) - delta.y * kRadiansPerPixel;
    pitch = std::clamp(pitch, -1.55f, 1.55f);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}
}  // namespace

bool orbitCamera(CameraSettings& cam, glm::vec3 pivot, glm::vec2 mouseDelta) {
    if (mouseDelta == glm::vec2(0.0f)) return false;
    const glm::vec3 before = forwardOf(cam), after = rotate(before, mouseDelta);
    const float yaw0 = std::atan2(before.x, -before.z), yaw1 = std::atan2(after.x, -after.z);
    const float pitch0 = std::asin(std::clamp(before.y, -1.0f, 1.0f)), pitch1 = std::asin(std::clamp(after.y, -1.0f, 1.0f));
    const glm::vec3 horizontal = glm::cross(before, glm::vec3(0.0f, 1.0f, 0.0f));
    if (glm::length(horizontal) < 1e-6f) return false;  // straight up or down: no right axis
    // Pitch about the camera's right axis, then yaw about world up (a larger yaw turns towards +x,
    // a negative turn about +y): the rotation that takes the old forward to the new one.
    const glm::quat turn = glm::angleAxis(-(yaw1 - yaw0), glm::vec3(0.0f, 1.0f, 0.0f)) *
                           glm::angleAxis(pitch1 - pitch0, glm::normalize(horizontal));
    cam.position = pivot + turn * (cam.position - pivot);
    cam.target = pivot + turn * (cam.target - pivot);
    return true;
}

void frameBounds(CameraSettings& cam, const csm::Aabb& b) {
    glm::vec3 centre = b.center();
    float radius = std::max(0.5f * glm::length(b.extent()), 0.1f);
    float distance = radius / std::sin(0.5f * glm::radians(cam.fovY)) * 1.05f;
    const glm::vec3 forward = forwardOf(cam);  // before the target moves: the view keeps its direction
    cam.target = centre;
    cam.position = centre - forward * distance;
    cam.farPlane = std::max(cam.farPlane, distance + 2.0f * radius);
}

bool updateFlyCamera(CameraSettings& cam, FlyState& st, const FlyInput& in, const csm::Aabb& bounds) {
    CameraSettings before = cam;
    if (in.wheel != 0.0f) st.speed = std::clamp(st.speed * std::pow(1.2f, in.wheel), 0.05f, 5000.0f);
    if (in.frameScene) frameBounds(cam, bounds);
    glm::vec3 fwd = forwardOf(cam);
    float distance = std::max(glm::length(cam.target - cam.position), 1.0f);
    if (in.look) fwd = rotate(fwd, in.mouseDelta);
    glm::vec3 right = glm::normalize(glm::abs(fwd.y) > 0.999f ? glm::vec3(1, 0, 0) : glm::cross(fwd, glm::vec3(0, 1, 0)));
    glm::vec3 up = glm::cross(right, fwd);
    glm::vec3 move(0.0f);
    if (in.look) {
        move += fwd * (float(in.forward) - float(in.back));
        move += right * (float(in.right) - float(in.left));
        move += glm::vec3(0, 1, 0) * (float(in.up) - float(in.down));
    }
    glm::vec3 delta = move * st.speed * in.dt;
    if (in.pan) delta += (-right * in.mouseDelta.x + up * in.mouseDelta.y) * (st.speed * 0.01f);
    cam.position += delta;
    cam.target = cam.position + fwd * distance;
    return !(cam == before);
}

}  // namespace st::app
