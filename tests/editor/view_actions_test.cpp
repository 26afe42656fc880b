// Camera actions do not change tuning settings behind the artist's back (issue 13 #4).
#include "app/editor/fly_camera.h"
#include "app/editor/view_actions.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using namespace st;
using namespace st::app;

TEST(ViewActionsTest, FrameSceneMovesTheCameraAndKeepsNearAndFar) {
    CameraSettings cam;
    cam.nearPlane = 0.5f;
    cam.farPlane = 1500.0f;
    const csm::Aabb box{{-2000, 0, -2000}, {2000, 300, 2000}};  // ~4 km across: framing needs ~6 km
    CameraSettings reference = cam;
    frameBounds(reference, box);  // what F used to do: far grew to fit
    ASSERT_GT(reference.farPlane, 1500.0f);
    const std::string note = frameKeepingClipPlanes(cam, box);
    EXPECT_EQ(cam.nearPlane, 0.5f);
    EXPECT_EQ(cam.farPlane, 1500.0f);
    EXPECT_EQ(cam.target, box.center());
    EXPECT_NEAR(glm::length(cam.target - cam.position), 750.0f, 0.1f) << "half the far plane: the middle stays visible";
    EXPECT_NEAR(glm::dot(glm::normalize(cam.target - cam.position), glm::normalize(reference.target - reference.position)), 1.0f, 1e-5f);
    EXPECT_NE(note.find("past the far plane (1500 m)"), std::string::npos) << note;
    CameraSettings small;
    EXPECT_EQ(frameKeepingClipPlanes(small, csm::Aabb{{-1, 0, -1}, {1, 1, 1}}), "");
    EXPECT_LT(glm::length(small.position - small.target), small.farPlane);
}

// The default preset's camera looks 13 deg down; framed, it looked 60 deg up from under the
// ground, because the direction was taken after the target had moved to the centre.
TEST(ViewActionsTest, FrameSceneKeepsTheViewingDirection) {
    CameraSettings cam;
    cam.position = {0, 6, 14};
    cam.target = {0, 0, -12};
    const glm::vec3 before = glm::normalize(cam.target - cam.position);
    frameKeepingClipPlanes(cam, csm::Aabb{{-50, 0, -50}, {50, 60, 50}});
    const glm::vec3 after = glm::normalize(cam.target - cam.position);
    EXPECT_NEAR(glm::dot(before, after), 1.0f, 1e-5f);
    EXPECT_GT(cam.position.y, 30.0f) << "above the centre, looking down as before";
}

// Issue 39 #8: F on a town on a 2 km terrain framed the terrain; the houses became a speck.
TEST(ViewActionsTest, FrameSceneLeavesOutWhatSprawls) {
    const csm::Aabb terrain{{-1000, -5, -1000}, {1000, 50, 1000}};
    std::vector<csm::Aabb> items{terrain};
    for (int i = 0; i < 6; ++i) items.push_back({{float(i) * 10.0f, 0, 0}, {float(i) * 10.0f + 8.0f, 6, 8}});
    const csm::Aabb framed = framingBounds(items, terrain);
    EXPECT_FLOAT_EQ(framed.min.x, 0.0f);
    EXPECT_FLOAT_EQ(framed.max.x, 58.0f);
    EXPECT_FLOAT_EQ(framed.max.y, 6.0f) << "the houses, not the terrain";
    EXPECT_FLOAT_EQ(framingBounds({items.begin(), items.begin() + 2}, terrain).max.x, 1000.0f) << "too few items to judge";
    std::vector<csm::Aabb> similar(items.begin() + 1, items.end());
    EXPECT_FLOAT_EQ(framingBounds(similar, terrain).max.x, 1000.0f) << "nothing sprawls: the whole scene";
}

TEST(ViewActionsTest, ACameraGestureEndsWhenTheButtonIsReleased) {
    CameraGesture g;
    CameraSettings a, b = a, c = a;
    b.position.x += 1.0f;
    c.position.x += 2.0f;
    EXPECT_FALSE(g.update(a, a, true));   // held, nothing moved yet
    EXPECT_FALSE(g.update(a, b, true));   // moving
    EXPECT_FALSE(g.update(b, c, true));
    const auto start = g.update(c, c, false);  // released
    ASSERT_TRUE(start);
    EXPECT_EQ(*start, a);  // one step from where the gesture began
    EXPECT_FALSE(g.update(c, c, false));  // nothing pending any more
    EXPECT_FALSE(g.update(c, c, true));   // a click that moves nothing is no step
    EXPECT_FALSE(g.update(c, c, false));
}
