// Comparator self-tests: the golden comparison must be able to fail.
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/image_compare.h"

using namespace st;

namespace {
class ImageCompareGLTest : public test::GLTest {
protected:
    Rgba8Image reference() {
        Scene scene = makeBuiltinScene("box-over-plane");
        Renderer r(scene);
        Settings s;
        s.scene = "builtin:box-over-plane";
        s.camera.position = {0.0f, 8.0f, 12.0f};
        s.camera.target = {0.0f, 1.0f, 0.0f};
        s.output = {320, 180, View::Shaded};
        return test::renderImage(r, s);
    }
};
}  // namespace

TEST_F(ImageCompareGLTest, IdenticalImagesPass) {
    Rgba8Image img = reference();
    EXPECT_TRUE(test::compareImages(img, img, {}).pass);
}

TEST_F(ImageCompareGLTest, OnePixelShiftFails) {
    Rgba8Image img = reference();
    test::CompareResult r = test::compareImages(test::shifted(img, 1, 0), img, {});
    EXPECT_FALSE(r.pass) << r.summary();
    r = test::compareImages(test::shifted(img, 0, 1), img, {});
    EXPECT_FALSE(r.pass) << r.summary();
}

TEST_F(ImageCompareGLTest, SmallUniformOffsetPassesLargeFails) {
    Rgba8Image img = reference();
    Rgba8Image brighter = img, muchBrighter = img;
    for (auto& p : brighter.pixels) p = std::uint8_t(std::min(255, p + 3));
    for (auto& p : muchBrighter.pixels) p = std::uint8_t(std::min(255, p + 12));
    EXPECT_TRUE(test::compareImages(brighter, img, {}).pass);
    EXPECT_FALSE(test::compareImages(muchBrighter, img, {}).pass);
}

TEST_F(ImageCompareGLTest, SizeMismatchFails) {
    Rgba8Image img = reference();
    Rgba8Image small{2, 2, std::vector<std::uint8_t>(16, 0)};
    EXPECT_FALSE(test::compareImages(small, img, {}).pass);
}
