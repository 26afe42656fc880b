// Why `shadowtune check` has no perceptual image measure. Issue 20 asks for one "if a Debian library
// gives one"; Debian 12's OpenImageIO 2.4 has Yee's metric, ImageBufAlgo::compare_Yee, but its
// Gaussian pyramid reads channel 1 of the one-channel luminance image it builds, which reads as 0:
// no luminance change ever fails (src/libOpenImageIO/imagebufalgo_yee.cpp, GaussianPyramid::value),
// only the colour test (CIE a*, b*) can. A shadow is a luminance change, so the measure would pass
// any shadow regression. When this test fails, the library sees luminance: give the suite's image
// tolerance a perceptual share (check/image_diff.h).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

namespace {

using OIIO::ImageBuf;
namespace IBA = OIIO::ImageBufAlgo;

// 160x90 mid grey with a 20x20 block of `block` at (40, 20).
ImageBuf greyWithBlock(const float (&block)[3], bool withBlock = true) {
    ImageBuf b(OIIO::ImageSpec(160, 90, 3, OIIO::TypeDesc::UINT8));
    const float grey[3] = {0.5f, 0.5f, 0.5f};
    IBA::fill(b, grey);
    if (withBlock) IBA::fill(b, block, OIIO::ROI(40, 60, 20, 40));
    return b;
}

TEST(PerceptualLibraryTest, DebiansCompareYeeFailsAColourChangeButNoLuminanceChange) {
    const float none[3] = {0.5f, 0.5f, 0.5f}, white[3] = {1.0f, 1.0f, 1.0f}, black[3] = {0.0f, 0.0f, 0.0f},
                red[3] = {1.0f, 0.0f, 0.0f};
    const ImageBuf grey = greyWithBlock(none, false);
    IBA::CompareResults r;
    EXPECT_EQ(IBA::compare_Yee(grey, greyWithBlock(none), r), 0) << "identical images";
    // The call is right: a saturated red block, a colour change, fails on each of its 400 pixels.
    EXPECT_EQ(IBA::compare_Yee(grey, greyWithBlock(red), r), 400);
    // A white or a black block on grey is as visible, and passes: the luminance test never fails.
    EXPECT_EQ(IBA::compare_Yee(grey, greyWithBlock(white), r), 0) << "OpenImageIO sees luminance now: see the header";
    EXPECT_EQ(IBA::compare_Yee(grey, greyWithBlock(black), r), 0) << "OpenImageIO sees luminance now: see the header";
}

}  // namespace
