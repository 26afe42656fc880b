// Issue 13 #10: with a still view the editor shows the image it holds instead of rendering
// again. That is exact only if rendering the same inputs again gives the same pixels whatever
// was rendered in between (the cascade cache, the depth bounds), and if a map an update interval
// deferred is caught up: checked here with the real renderer against fresh renders.
#include "app/editor/scene_frame.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/scene.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <cstdint>
#include <vector>

namespace st::app {
namespace {

class SceneFrameGLTest : public test::GLTest {
protected:
    std::vector<std::uint8_t> freshRender(const Scene& scene, const Settings& s) {
        Renderer r(scene);
        r.render(s);
        return r.readRgba8();
    }
};

TEST_F(SceneFrameGLTest, TheHeldImageIsWhatAFreshRenderOfTheSameInputsGives) {
    Settings s = test::presetAtTestSize("default", 192, 108);
    const Scene scene = loadScene(s.scene, ST_PRESET_DIR);
    Renderer r(scene);
    SceneFrameCache cache;
    SceneFrameInputs in;
    in.live = s;
    const FrameStats first = r.render(s);
    cache.rendered(in, &first, nullptr);
    const std::vector<std::uint8_t> held = r.readRgba8();
    EXPECT_EQ(cache.check(in), "") << "still: reused";
    EXPECT_EQ(held, freshRender(scene, s)) << "the held image is the fresh render's";

    // Another frame in between (a moved camera, an interactive one), then back: the same pixels.
    SceneFrameInputs moved = in;
    moved.live = interactiveMaps(s);
    moved.live.camera.position.x += 3.0f;
    moved.live.output.width = 96, moved.live.output.height = 54;
    EXPECT_NE(cache.check(moved), "");
    const FrameStats movedStats = r.render(moved.live);
    cache.rendered(moved, &movedStats, nullptr);
    EXPECT_NE(r.readRgba8().size(), held.size());
    EXPECT_EQ(cache.check(in), "inputs changed") << "the full frame after the gesture is rendered";
    const FrameStats back = r.render(s);
    cache.rendered(in, &back, nullptr);
    EXPECT_EQ(r.readRgba8(), held);
    EXPECT_EQ(cache.check(in), "");
}

TEST_F(SceneFrameGLTest, AFrameWithADeferredMapIsRenderedUntilTheMapIsDrawn) {
    Settings s = test::presetAtTestSize("default", 192, 108);
    s.cascades.updateInterval = {1.0f, 1.0f, 1.0f, 3.0f};
    s.cascades.count = 4;
    const Scene scene = loadScene(s.scene, ST_PRESET_DIR);
    Renderer r(scene);
    SceneFrameCache cache;
    SceneFrameInputs in;
    r.render(s);
    Settings still = s;
    still.camera.position += glm::vec3(40.0f, 0.0f, -25.0f);  // far enough to move the last cascade's box
    still.camera.target += glm::vec3(40.0f, 0.0f, -25.0f);
    in.live = still;
    int renders = 0;
    for (std::string why = "first frame"; !why.empty() && renders < 10; why = cache.check(in), ++renders) {
        const FrameStats stats = r.render(still);
        if (renders == 0) ASSERT_TRUE(mapsPending(stats)) << "the interval defers cascade 3: " << stats.cascades[3].mapReason;
        cache.rendered(in, &stats, nullptr);
    }
    EXPECT_GT(renders, 1) << "the deferred map was drawn in a later frame";
    EXPECT_LT(renders, 10);
    EXPECT_EQ(r.readRgba8(), freshRender(scene, still)) << "once no map waits, the held image is the fresh render's";
}

// Issue 39 #1: every full frame after a move re-allocated the full-size maps (the preview's
// smaller ones had replaced them): 145 ms of a 4 x 4096² first frame. A preview frame now draws
// into a set of its own; the full frame after it finds its maps, and still draws what a fresh
// renderer would.
TEST_F(SceneFrameGLTest, AnInteractiveFrameLeavesTheFullSizeMapsInPlace) {
    const Settings s = test::presetAtTestSize("default", 192, 108);
    const Scene scene = loadScene(s.scene, ST_PRESET_DIR);
    Renderer r(scene);
    r.render(s);
    const GLuint fullTexture = r.shadowMaps().texture(0);
    const int fullAllocations = r.shadowMaps().allocations();
    Settings moved = s;
    for (int gesture = 0; gesture < 2; ++gesture) {
        moved.camera.position.x += 3.0f;
        Settings preview = interactiveMaps(moved);
        preview.output.width = 96, preview.output.height = 54;
        r.setOptions({.previewMaps = true});
        r.render(preview);
        ASSERT_EQ(r.shadowMaps().layout().tiles[0].size, s.cascades.mapSize / 2) << "the preview drew its smaller maps";
        r.setOptions({});
        r.render(moved);  // the first full frame after the move
        EXPECT_EQ(r.shadowMaps().allocations(), fullAllocations + 1) << "gesture " << gesture << ": one preview set, ever";
        EXPECT_EQ(r.shadowMaps().texture(0), fullTexture) << "the full-size maps were re-created";
        EXPECT_EQ(r.shadowMaps().held(MapSet::Preview).tiles[0].size, s.cascades.mapSize / 2) << "listed for the memory table";
        EXPECT_EQ(r.readRgba8(), freshRender(scene, moved)) << "the kept maps were redrawn for the moved view";
    }
}

}  // namespace
}  // namespace st::app
