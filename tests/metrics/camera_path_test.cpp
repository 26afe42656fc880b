// The cascade camera along a preset's path: even spacing over the frames, linear in between.
#include "metrics/camera_path.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace st::metrics {
namespace {

Settings twoKeyPath(int frames) {
    Settings s;
    s.camera.nearPlane = 0.5f;
    s.path.frames = frames;
    s.path.keyframes = {{.position = {0, 2, 10}, .target = {0, 0, 0}, .fovY = 40.0f},
                        {.position = {4, 2, 10}, .target = {4, 0, 0}, .fovY = 60.0f}};
    return s;
}

TEST(CameraPathTest, EndsOnTheKeyframesAndKeepsNearFar) {
    const Settings s = twoKeyPath(5);
    EXPECT_EQ(cameraOnPath(s, 0).position, glm::vec3(0, 2, 10));
    EXPECT_EQ(cameraOnPath(s, 4).position, glm::vec3(4, 2, 10));
    EXPECT_EQ(cameraOnPath(s, 4).fovY, 60.0f);
    EXPECT_EQ(cameraOnPath(s, 2).nearPlane, 0.5f);
}

TEST(CameraPathTest, EvenStepsInBetween) {
    const Settings s = twoKeyPath(5);
    EXPECT_FLOAT_EQ(cameraOnPath(s, 1).position.x, 1.0f);
    EXPECT_FLOAT_EQ(cameraOnPath(s, 2).target.x, 2.0f);
    EXPECT_FLOAT_EQ(cameraOnPath(s, 3).fovY, 55.0f);
}

TEST(CameraPathTest, ThreeKeyframesShareTheFrames) {
    Settings s = twoKeyPath(5);
    s.path.keyframes.push_back({.position = {4, 2, 6}, .target = {4, 0, -4}, .fovY = 60.0f});
    EXPECT_FLOAT_EQ(cameraOnPath(s, 2).position.x, 4.0f);  // the middle keyframe at the middle frame
    EXPECT_FLOAT_EQ(cameraOnPath(s, 3).position.z, 8.0f);
    EXPECT_EQ(cameraOnPath(s, 4).position, glm::vec3(4, 2, 6));
}

TEST(CameraPathTest, OneKeyframeIsAStill) {
    Settings s = twoKeyPath(3);
    s.path.keyframes.resize(1);
    EXPECT_EQ(cameraOnPath(s, 2).position, glm::vec3(0, 2, 10));
    EXPECT_EQ(atPathFrame(s, 1).camera.fovY, 40.0f);
    s.path.keyframes.clear();
    EXPECT_THROW(cameraOnPath(s, 0), std::invalid_argument);
}

}  // namespace
}  // namespace st::metrics
