// Issue 13 item 5: the side view's camera frustum is drawn in a colour no cascade uses (white),
// including its far face, which is also the last cascade's far split plane; each inner split
// plane and each light box keeps its cascade's tint. CPU only (the line list), no context.
#include "renderer/csm/cascade_plan.h"
#include "renderer/render/cascade_tints.h"
#include "renderer/render/side_view.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

namespace st {

TEST(SideViewLinesTest, FrustumIsWhiteAndNoCascadeTintIsWhite) {
    for (const LinearRgb t : kCascadeTints) EXPECT_FALSE(t.r >= 0.99f && t.g >= 0.99f && t.b >= 0.99f);
    const Settings s = loadPreset(ST_PRESET_DIR "/default.json");
    const csm::CascadePlan plan = csm::planCascades(s, 16.0f / 9.0f, {{-50.0f, 0.0f, -50.0f}, {50.0f, 20.0f, 50.0f}});
    const std::vector<LineVertex> lines = cascadeWireframes(plan);
    const glm::mat4 view = plan.vsView;
    const int n = static_cast<int>(plan.cascades.size());
    int white = 0;
    std::vector<int> splitPlaneVertices(std::size_t(n), 0);
    for (const LineVertex& v : lines) {
        const float depth = -(view * glm::vec4(v.position, 1.0f)).z;
        if (v.color == glm::vec3(1.0f)) {
            ++white;
            continue;
        }
        for (int i = 0; i < n; ++i)
            if (v.color == cascadeTint(i) && std::abs(depth - plan.splits[std::size_t(i) + 1]) < 1e-3f * plan.splits.back())
                ++splitPlaneVertices[std::size_t(i)];
    }
    EXPECT_EQ(white, 24) << "the frustum's 12 edges";
    for (int i = 0; i + 1 < n; ++i) EXPECT_GE(splitPlaneVertices[std::size_t(i)], 8) << "split plane " << i << " in its tint";
    EXPECT_EQ(splitPlaneVertices[std::size_t(n) - 1], 0) << "the far face is the frustum's: white, not cascade " << n - 1 << "'s tint";
}

}  // namespace st
