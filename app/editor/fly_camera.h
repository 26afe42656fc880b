#pragma once
// Editor camera control like other 3D editors: right mouse + WASD/QE fly, wheel changes speed,
// middle mouse pans, F frames the scene. Pure logic over CameraSettings, so it is unit-tested
// without a window.
#include "renderer/csm/geometry.h"
#include "renderer/settings/settings.h"

#include <glm/vec2.hpp>

namespace st::app {

struct FlyInput {
    float dt = 0.0f;               // seconds since the last frame
    glm::vec2 mouseDelta{0.0f};    // pixels, +x right, +y down
    bool look = false;             // right mouse held
    bool pan = false;              // middle mouse held
    float wheel = 0.0f;            // notches, + = away from the user
    bool forward = false, back = false, left = false, right = false, down = false, up = false;
    bool frameScene = false;       // F
};

struct FlyState {
    float speed = 10.0f;           // metres per second; the wheel scales it
};

// Returns true if the camera changed.
bool updateFlyCamera(CameraSettings& cam, FlyState& state, const FlyInput& in, const csm::Aabb& wsSceneBounds);

// Orbit (issue 21 #3, Alt + left drag): turns the camera around `pivot` (the point picked under
// the cursor when the drag began, or the target) by the mouse movement, as looking around would
// turn it, so the pivot keeps its place in the picture and its distance. Pitch stops short of
// straight up or down. Returns true if the camera changed.
bool orbitCamera(CameraSettings& cam, glm::vec3 pivot, glm::vec2 mouseDelta);

// Camera position and target that show the whole bounds from the current viewing direction.
void frameBounds(CameraSettings& cam, const csm::Aabb& wsBounds);

}  // namespace st::app
