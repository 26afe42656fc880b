// The CPU alpha test the ground truth uses for cut-out (MASK) materials.
#include "metrics/alpha_cutout.h"

#include <gtest/gtest.h>

namespace st::metrics {
namespace {

// 2x1 texels: alpha 0 on the left, 255 on the right.
Image halfTransparent() { return Image{2, 1, {255, 255, 255, 0, 255, 255, 255, 255}}; }

TEST(AlphaCutoutTest, BilinearAtTexelCentresAndBetween) {
    const Image img = halfTransparent();
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.25f, 0.5f}), 0.0f);   // centre of texel 0
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.75f, 0.5f}), 1.0f);   // centre of texel 1
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.5f, 0.5f}), 0.5f);    // halfway
    EXPECT_FLOAT_EQ(sampleAlpha(img, {1.25f, 0.5f}), 0.0f);   // GL_REPEAT
    EXPECT_FLOAT_EQ(sampleAlpha(img, {-0.25f, 0.5f}), 1.0f);
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.0f, 0.5f}), 0.5f);    // the seam blends both ends
}

TEST(AlphaCutoutTest, MaterialAlphaMultipliesTheBaseColour) {
    Scene scene;
    scene.images.push_back(halfTransparent());
    Material m;
    m.baseColorTexture = 0;
    m.baseColor.a = 0.5f;
    EXPECT_FLOAT_EQ(materialAlpha(scene, m, {0.75f, 0.5f}), 0.5f);
    m.baseColorTexture = 3;  // out of range: drawn untextured, as SceneGpu does
    EXPECT_FLOAT_EQ(materialAlpha(scene, m, {0.25f, 0.5f}), 0.5f);
}

TEST(AlphaCutoutTest, OnlyMaskMaterialsAreCut) {
    Scene scene;
    scene.images.push_back(halfTransparent());
    Material m;
    m.baseColorTexture = 0;
    EXPECT_FALSE(cutOut(scene, m, {0.25f, 0.5f}));  // opaque mode ignores alpha
    m.alphaMask = true;
    EXPECT_TRUE(cutOut(scene, m, {0.25f, 0.5f}));
    EXPECT_FALSE(cutOut(scene, m, {0.75f, 0.5f}));
    m.alphaCutoff = 0.4f;
    EXPECT_FALSE(cutOut(scene, m, {0.5f, 0.5f}));  // 0.5 >= cutoff: kept, like the GL test
}

}  // namespace
}  // namespace st::metrics
