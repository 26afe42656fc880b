// The side view's split-plane handles: each sits where the side camera shows the centre of the
// split plane (the centroid of the slice's far corners, computed here from the frustum corners),
// and its per-metre direction is where the next centimetres of depth go.
#include "app/editor/side_split_handles.h"
#include "renderer/csm/frustum.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

namespace st::app {

TEST(SideSplitHandlesTest, HandlesSitOnTheSplitPlanesCentres) {
    const Settings s = loadPreset(ST_PRESET_DIR "/default.json");
    const csm::CascadePlan plan = csm::planCascades(s, 16.0f / 9.0f, {{-50.0f, 0.0f, -50.0f}, {50.0f, 20.0f, 50.0f}});
    const OrbitCamera orbit;
    const float aspect = 4.0f / 3.0f;
    const std::vector<ui::SideSplitHandle> handles = sideSplitHandles(plan, orbit, aspect);
    ASSERT_EQ(handles.size(), plan.splits.size() - 2);
    const csm::CameraParams side = sideCamera(plan, orbit, aspect);
    const glm::mat4 viewProj = csm::projectionMatrix(side) * csm::viewMatrix(side);
    auto uvOf = [&](glm::vec3 ws) {
        const glm::vec4 cs = viewProj * glm::vec4(ws, 1.0f);
        return glm::vec2(0.5f + 0.5f * cs.x / cs.w, 0.5f - 0.5f * cs.y / cs.w);
    };
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const csm::Corners c = csm::sliceCornersFromCamera(plan.camera, plan.splits[i], plan.splits[i + 1]);
        const glm::vec3 centre = (c[4] + c[5] + c[6] + c[7]) * 0.25f;  // far face of slice i
        const glm::vec2 want = uvOf(centre);
        EXPECT_NEAR(handles[i].uv.x, want.x, 1e-4f) << i;
        EXPECT_NEAR(handles[i].uv.y, want.y, 1e-4f) << i;
        const csm::Corners further = csm::sliceCornersFromCamera(plan.camera, plan.splits[i], plan.splits[i + 1] + 1.0f);
        const glm::vec2 oneMetre = uvOf((further[4] + further[5] + further[6] + further[7]) * 0.25f) - want;
        EXPECT_NEAR(handles[i].uvPerMetre.x, oneMetre.x, 0.05f * glm::length(oneMetre) + 1e-6f) << i;
        EXPECT_NEAR(handles[i].uvPerMetre.y, oneMetre.y, 0.05f * glm::length(oneMetre) + 1e-6f) << i;
    }
}

}  // namespace st::app
