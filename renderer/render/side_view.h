#pragma once
// The side camera: an orbit around the shadowed part of the main camera's frustum, and the
// wireframes it shows (the main frustum with its split planes, each cascade's light box in that
// cascade's tint, including its extension toward the light).
#include "renderer/csm/cascade_plan.h"

#include <glm/vec3.hpp>

#include <vector>

namespace st {

struct OrbitCamera {
    float yawDeg = -50.0f;   // around world +Y, 0 = looking along -Z
    float pitchDeg = 35.0f;  // above the horizon
    float zoom = 1.0f;       // multiplies the fitted distance
    glm::vec3 panOffset{0.0f};
};

struct LineVertex {
    glm::vec3 position;
    glm::vec3 color;
};

// Camera looking at the centre of the cascades' coverage from outside, far enough to see it all.
csm::CameraParams sideCamera(const csm::CascadePlan& plan, const OrbitCamera& orbit, float aspect);

// GL_LINES vertex pairs: main frustum (white) with its split planes (tinted), light boxes (tinted).
std::vector<LineVertex> cascadeWireframes(const csm::CascadePlan& plan);

// The one table of cascade tints, linear RGB: the cascades view reads them from CascadeData::tint
// (shaders/interface.h), the wireframes and the editor's legends from here.
glm::vec3 cascadeTint(int cascade);

}  // namespace st
