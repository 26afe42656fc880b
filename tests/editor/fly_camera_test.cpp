#include "app/editor/fly_camera.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

using namespace st;
using namespace st::app;

namespace {
CameraSettings camera() {
    CameraSettings c;
    c.position = {0, 2, 10};
    c.target = {0, 2, 0};
    return c;
}
const csm::Aabb kBounds{{-5, 0, -5}, {5, 4, 5}};
}  // namespace

TEST(FlyCameraTest, ForwardWithRightMouseMovesAlongViewAtSpeed) {
    CameraSettings c = camera();
    FlyState st;
    st.speed = 4.0f;
    FlyInput in;
    in.dt = 0.5f;
    in.look = true;
    in.forward = true;
    EXPECT_TRUE(updateFlyCamera(c, st, in, kBounds));
    EXPECT_NEAR(c.position.z, 8.0f, 1e-4f);
    EXPECT_NEAR(glm::length(c.target - c.position), 10.0f, 1e-3f);  // keeps its look distance
}

TEST(FlyCameraTest, KeysWithoutRightMouseDoNothing) {
    CameraSettings c = camera();
    FlyState st;
    FlyInput in;
    in.dt = 0.5f;
    in.forward = true;
    EXPECT_FALSE(updateFlyCamera(c, st, in, kBounds));
    EXPECT_EQ(c, camera());
}

TEST(FlyCameraTest, MouseLookTurnsButNeverFlipsOverThePole) {
    CameraSettings c = camera();
    FlyState st;
    FlyInput in;
    in.look = true;
    in.mouseDelta = {0.0f, -100000.0f};  // far more than straight up
    updateFlyCamera(c, st, in, kBounds);
    glm::vec3 fwd = glm::normalize(c.target - c.position);
    EXPECT_GT(fwd.y, 0.99f);
    EXPECT_LT(fwd.y, 1.0f);
    EXPECT_TRUE(std::isfinite(c.target.x) && std::isfinite(c.target.z));
}

TEST(FlyCameraTest, WheelScalesSpeedWithinLimits) {
    CameraSettings c = camera();
    FlyState st;
    FlyInput in;
    in.wheel = 1.0f;
    updateFlyCamera(c, st, in, kBounds);
    EXPECT_NEAR(st.speed, 12.0f, 1e-4f);
    in.wheel = -1000.0f;
    updateFlyCamera(c, st, in, kBounds);
    EXPECT_GE(st.speed, 0.05f);
}

TEST(FlyCameraTest, FrameSceneCentresTheBoundsInView) {
    CameraSettings c = camera();
    c.position = {100, 50, 100};
    c.target = {99, 50, 99};
    FlyState st;
    FlyInput in;
    in.frameScene = true;
    updateFlyCamera(c, st, in, kBounds);
    EXPECT_NEAR(glm::length(c.target - kBounds.center()), 0.0f, 1e-4f);
    float radius = 0.5f * glm::length(kBounds.extent());
    float distance = glm::length(c.position - c.target);
    EXPECT_GE(distance * std::sin(glm::radians(c.fovY / 2)), radius);  // the sphere fits the view
}

TEST(FlyCameraTest, MiddleMousePansPositionAndTargetTogether) {
    CameraSettings c = camera();
    FlyState st;
    FlyInput in;
    in.pan = true;
    in.mouseDelta = {50.0f, 0.0f};
    updateFlyCamera(c, st, in, kBounds);
    EXPECT_NEAR(c.position.x, c.target.x, 1e-4f);
    EXPECT_NE(c.position.x, 0.0f);
}

// Issue 21 #3: an orbit around a picked point keeps the point's distance and its place in the
// picture (its direction in the camera's own frame), and turns the view as a look would.
TEST(OrbitCameraTest, ThePivotKeepsItsDistanceAndItsPlaceInThePicture) {
    CameraSettings cam;
    cam.position = {10.0f, 4.0f, 12.0f};
    cam.target = {0.0f, 1.0f, 0.0f};
    const glm::vec3 pivot{1.5f, 0.0f, 2.0f};  // a point off the view's centre, under the cursor
    auto inCamera = [](const CameraSettings& c, glm::vec3 p) {
        const glm::vec3 f = glm::normalize(c.target - c.position);
        const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f)));
        const glm::vec3 u = glm::cross(r, f);
        const glm::vec3 d = p - c.position;
        return glm::vec3(glm::dot(d, r), glm::dot(d, u), glm::dot(d, f));
    };
    const glm::vec3 seen = inCamera(cam, pivot);
    const float distance = glm::length(cam.position - pivot), targetDistance = glm::length(cam.target - cam.position);
    ASSERT_TRUE(orbitCamera(cam, pivot, {120.0f, -40.0f}));
    EXPECT_NEAR(glm::length(cam.position - pivot), distance, 1e-3f);
    EXPECT_NEAR(glm::length(cam.target - cam.position), targetDistance, 1e-3f);
    const glm::vec3 after = inCamera(cam, pivot);
    EXPECT_NEAR(after.x, seen.x, 1e-3f);
    EXPECT_NEAR(after.y, seen.y, 1e-3f);
    EXPECT_NEAR(after.z, seen.z, 1e-3f);
    // The yaw the mouse asked for: 120 px at 0.004 rad a pixel.
    const glm::vec3 f = glm::normalize(cam.target - cam.position);
    const glm::vec3 f0 = glm::normalize(glm::vec3{0.0f, 1.0f, 0.0f} - glm::vec3{10.0f, 4.0f, 12.0f});
    EXPECT_NEAR(std::atan2(f.x, -f.z) - std::atan2(f0.x, -f0.z), 0.48f, 1e-3f);
    EXPECT_FALSE(orbitCamera(cam, pivot, {0.0f, 0.0f}));
}
