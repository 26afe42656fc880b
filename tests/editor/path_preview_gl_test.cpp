// Preview path's frames, rendered headless: each must be what `render` gives for that path frame
// (a fresh renderer, the camera at the path's pose), and the flicker measured on the way must be
// measure's (metrics::measureFlicker with its own renderer and pass) for the same path and size.
#include "app/editor/path_preview_render.h"
#include "metrics/camera_path.h"
#include "metrics/measure_session.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <cstdlib>

namespace st::app {
namespace {

class PathPreviewGLTest : public test::GLTest {};

int maxChannelDiff(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    int worst = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (i % 4 != 3) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
    return worst;
}

TEST_F(PathPreviewGLTest, EachFrameIsRenderOfThatPathFrameAndTheFlickerIsMeasures) {
    Settings s = test::presetAtTestSize("default");  // the yard, a 16-frame path
    ASSERT_GT(s.path.frames, 2);
    s.path.frames = 6;  // enough pairs for a flip rate, few renders
    const auto scene = std::make_shared<const Scene>(loadScene(s.scene, ST_PRESET_DIR));

    Renderer editorRenderer(*scene);
    editorRenderer.render(s);  // the editor's renderer held the live frame before
    PathPreviewRender preview;
    while (!preview.done(s)) preview.renderNext(editorRenderer, s);
    ASSERT_EQ(int(preview.frames().size()), s.path.frames);

    Renderer fresh(*scene);
    std::vector<std::uint8_t> previous;
    int framesThatDiffer = 0;
    for (int i = 0; i < s.path.frames; ++i) {
        fresh.render(metrics::atPathFrame(s, i));  // what `render` writes for the preset at that frame
        const std::vector<std::uint8_t> expected = fresh.readRgba8();
        const Rgba8Image& got = preview.frames()[std::size_t(i)];
        ASSERT_EQ(got.width, s.output.width);
        ASSERT_EQ(got.height, s.output.height);
        EXPECT_LE(maxChannelDiff(got.pixels, expected), 2) << "frame " << i;
        if (!previous.empty() && maxChannelDiff(previous, got.pixels) > 8) ++framesThatDiffer;
        previous = got.pixels;
    }
    EXPECT_EQ(framesThatDiffer, s.path.frames - 1) << "the camera moves along the path: every frame differs";

    Renderer measureRenderer(*scene);
    MeasurePass pass;
    std::vector<float> stdDev;
    const metrics::FlickerReport measured = metrics::measureFlicker(measureRenderer, pass, s, &stdDev);
    ASSERT_TRUE(preview.flicker().has_value());
    EXPECT_EQ(preview.flicker()->frames, measured.frames);
    EXPECT_EQ(preview.flicker()->samplePoints, measured.samplePoints);
    EXPECT_NEAR(preview.flicker()->flipRate, measured.flipRate, 1e-9);
    EXPECT_GT(measured.samplePoints, 0u);
    EXPECT_EQ(preview.flickerMap().width, s.output.width);
    EXPECT_EQ(preview.flickerMap().height, s.output.height);
}

}  // namespace
}  // namespace st::app
