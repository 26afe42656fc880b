#include "app/fly_camera.h"

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
