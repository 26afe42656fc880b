// The editor's A/B split, composed headless: left of the divider must be A's method rendered on
// the live view (a render of its own), right of it the live frame; the halves of two methods that
// differ must differ, so a split that showed one image twice would fail.
#include "app/editor/ab_split_render.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <cstdlib>

namespace st::app {
namespace {

class AbSplitGLTest : public test::GLTest {
protected:
    // Largest channel difference between a and b over columns [x0, x1).
    static int maxDiff(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int width, int height,
                       int x0, int x1, int* differing = nullptr) {
        int worst = 0, count = 0;
        for (int y = 0; y < height; ++y)
            for (int x = x0; x < x1; ++x) {
                int d = 0;
                for (int c = 0; c < 3; ++c) {
                    const std::size_t i = (std::size_t(y) * width + x) * 4 + c;
                    d = std::max(d, std::abs(int(a[i]) - int(b[i])));
                }
                worst = std::max(worst, d);
                count += d > 8 ? 1 : 0;
            }
        if (differing) *differing = count;
        return worst;
    }

    Settings live = test::presetAtTestSize("default");
    std::shared_ptr<const Scene> scene = std::make_shared<const Scene>(loadScene(live.scene, ST_PRESET_DIR));
    Renderer renderer{*scene};
};

TEST_F(AbSplitGLTest, LeftOfTheDividerIsARenderOfARightIsTheLiveFrame) {
    Settings a = live;  // A: one small cascade, no filter, another camera and light (not shown)
    a.cascades.count = 1;
    a.cascades.mapSize = 256;
    a.filter.kind = FilterKind::Hard;
    a.camera.position.x += 5.0f;
    a.light.azimuth += 40.0f;

    Settings expectedA = live;  // A's method alone on the live camera, light and size
    expectedA.cascades = a.cascades;
    expectedA.filter = a.filter;
    expectedA.bias = a.bias;
    renderer.render(expectedA);
    const std::vector<std::uint8_t> imageA = renderer.readRgba8();
    renderer.render(live);
    const std::vector<std::uint8_t> imageLive = renderer.readRgba8();
    const int w = renderer.width(), h = renderer.height();

    AbSplitRender ab;
    const float fraction = 0.4f;
    const FrameStats statsA = ab.renderA(renderer, aOnLive(a, live));
    EXPECT_EQ(statsA.cascades.size(), 1u);
    EXPECT_EQ(statsA.shadowMapBytes, std::size_t(256) * 256 * 4);
    const FrameStats statsLive = renderer.render(live);
    EXPECT_EQ(statsLive.cascades.size(), std::size_t(live.cascades.count));
    ab.composite(renderer.framebuffer(), fraction);
    const std::vector<std::uint8_t> split = renderer.readRgba8();

    const int x = dividerColumn(w, fraction);
    ASSERT_EQ(x, 128);
    EXPECT_LE(maxDiff(split, imageA, w, h, 0, x), 2);
    EXPECT_LE(maxDiff(split, imageLive, w, h, x, w), 2);
    int differing = 0;
    maxDiff(imageA, imageLive, w, h, 0, x, &differing);
    EXPECT_GT(differing, 50) << "the two methods should shade the left half differently";
}

TEST_F(AbSplitGLTest, DividerAtTheEdgesShowsOneSide) {
    EXPECT_EQ(dividerColumn(320, 0.0f), 0);
    EXPECT_EQ(dividerColumn(320, 1.0f), 320);
    EXPECT_EQ(dividerColumn(320, 1.5f), 320);
    AbSplitRender ab;
    Settings a = live;
    a.cascades.count = 1;
    ab.renderA(renderer, aOnLive(a, live));
    renderer.render(live);
    const std::vector<std::uint8_t> before = renderer.readRgba8();
    ab.composite(renderer.framebuffer(), 0.0f);  // nothing of A
    EXPECT_EQ(renderer.readRgba8(), before);
}

}  // namespace
}  // namespace st::app
