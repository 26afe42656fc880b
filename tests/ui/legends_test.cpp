// Issue 13 item 5: the colour keys use the colours the views draw. The cascade key is the one
// tint table sRGB-encoded as the shaders encode (tests/render ties the table to rendered
// cascades-view pixels); the density bar follows main.frag's fixed log scale: green at one
// screen pixel per texel, blue at 1/16, red at 16, clamped beyond.
#include "renderer/render/cascade_tints.h"
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"
#include "ui/legends.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace st;
using namespace st::test;

namespace {
float srgb(float linear) { return std::pow(linear, 1.0f / 2.2f); }
void expectColour(ImVec4 c, float r, float g, float b) {
    EXPECT_NEAR(c.x, srgb(r), 1e-5f);
    EXPECT_NEAR(c.y, srgb(g), 1e-5f);
    EXPECT_NEAR(c.z, srgb(b), 1e-5f);
}
}  // namespace

TEST(LegendsTest, CascadeKeyIsTheTintTableEncodedLikeTheShader) {
    for (int i = 0; i < 8; ++i) expectColour(ui::cascadeColour(i), kCascadeTints[i].r, kCascadeTints[i].g, kCascadeTints[i].b);
    expectColour(ui::cascadeColour(9), kCascadeTints[1].r, kCascadeTints[1].g, kCascadeTints[1].b);  // wraps as the renderer
}

TEST(LegendsTest, DensityBarFollowsTheFixedLogScale) {
    expectColour(ui::texelDensityColour(1.0f), 0.0f, 0.8f, 0.1f);      // ideal: green
    expectColour(ui::texelDensityColour(16.0f), 1.0f, 0.1f, 0.0f);     // aliasing: red
    expectColour(ui::texelDensityColour(1.0f / 16.0f), 0.1f, 0.2f, 1.0f);  // wasted: blue
    expectColour(ui::texelDensityColour(1000.0f), 1.0f, 0.1f, 0.0f);   // clamped
    expectColour(ui::texelDensityColour(4.0f), 0.5f, 0.45f, 0.05f);    // halfway in log2: v = 0.5
    EXPECT_GT(ui::texelDensityColour(8.0f).x, ui::texelDensityColour(2.0f).x);
}

TEST(LegendsTest, SceneShowsTheLegendOfItsDebugView) {
    UiDriver d;
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.frames(2);
    EXPECT_FALSE(d.drawn("legend.cascades"));
    EXPECT_FALSE(d.drawn("legend.density"));
    d.s.output.view = View::Cascades;
    d.frames(2);
    ASSERT_TRUE(d.drawn("legend.cascades"));
    const ImVec2 scene = d.last.scenePos;
    EXPECT_GE(d.rect("legend.cascades").min.x, scene.x);
    EXPECT_LE(d.rect("legend.cascades").max.x, scene.x + d.last.sceneSize.x) << "inside the scene viewport";
    EXPECT_GT(d.rect("legend.cascades").max.y - d.rect("legend.cascades").min.y, 4 * ImGui::GetTextLineHeight())
        << "one line per cascade";
    d.s.output.view = View::TexelGrid;
    d.frames(2);
    ASSERT_TRUE(d.drawn("legend.texelGrid"));
    EXPECT_LE(d.rect("legend.texelGrid").max.x, scene.x + d.last.sceneSize.x);
    EXPECT_GT(d.rect("legend.texelGrid").max.y - d.rect("legend.texelGrid").min.y, 5 * ImGui::GetTextLineHeight())
        << "a title and one line per cascade";
    d.s.output.view = View::TexelDensity;
    d.frames(2);
    EXPECT_TRUE(d.drawn("legend.density"));
    EXPECT_LE(d.rect("legend.density").max.y, scene.y + d.last.sceneSize.y);
}

// Issue 39 #9: after Tab the scene viewport shows the side camera's wireframes: their key goes
// with them, and the debug view's own legend does not (it belongs to the small picture now).
TEST(LegendsTest, AfterTabTheBigViewportCarriesTheWireframeKey) {
    UiDriver d;
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.s.output.view = View::TexelDensity;
    d.frames(2);
    ASSERT_TRUE(d.drawn("legend.density"));
    EXPECT_FALSE(d.drawn("legend.cascades"));
    d.in.sideViewSwapped = true;
    d.frames(2);
    EXPECT_TRUE(d.drawn("legend.cascades")) << "the side camera's wireframe key over the big viewport";
    EXPECT_FALSE(d.drawn("legend.density")) << "the main view's legend is not drawn over the side camera";
}
