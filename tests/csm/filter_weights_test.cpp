#include "renderer/csm/filter_weights.h"
#include "renderer/csm/light_fit.h"
#include "renderer/csm/splits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace st::csm {
namespace {

double sum(const std::array<float, kMaxFilterTaps>& w) {
    double s = 0.0;
    for (float v : w) s += v;
    return s;
}

TEST(FilterWeightsTest, EveryKernelSumsToOneAndIsSymmetric) {
    for (FilterWeights kind : {FilterWeights::Box, FilterWeights::Gaussian})
        for (int size = 1; size <= kMaxFilterTaps; size += 2) {
            const auto w = pcfWeights(kind, size);
            EXPECT_NEAR(sum(w), 1.0, 1e-6) << "size " << size;
            for (int k = 0; k < size; ++k) EXPECT_FLOAT_EQ(w[k], w[size - 1 - k]) << "size " << size << " tap " << k;
            for (int k = size; k < kMaxFilterTaps; ++k) EXPECT_EQ(w[k], 0.0f) << "unused tap " << k;
        }
}

TEST(FilterWeightsTest, BoxIsFlatAndGaussianFollowsItsSigma) {
    const auto box = pcfWeights(FilterWeights::Box, 5);
    for (int k = 0; k < 5; ++k) EXPECT_FLOAT_EQ(box[k], 0.2f);
    // 5 taps: sigma = 1.5 texels; the ratio of neighbouring taps is exp(-(2k+1) / (2 sigma^2)).
    EXPECT_FLOAT_EQ(pcfGaussianSigma(5), 1.5f);
    const auto g = pcfWeights(FilterWeights::Gaussian, 5);
    EXPECT_NEAR(g[3] / g[2], std::exp(-1.0 / 4.5), 1e-6);
    EXPECT_NEAR(g[4] / g[2], std::exp(-4.0 / 4.5), 1e-6);
    // Normalised by hand: 1 + 2 e^(-1/4.5) + 2 e^(-4/4.5).
    EXPECT_NEAR(g[2], 1.0 / (1.0 + 2.0 * std::exp(-1.0 / 4.5) + 2.0 * std::exp(-4.0 / 4.5)), 1e-6);
}

TEST(FilterWeightsTest, RejectsEvenAndOutOfRangeSizes) {
    EXPECT_THROW(pcfWeights(FilterWeights::Box, 4), std::invalid_argument);
    EXPECT_THROW(pcfWeights(FilterWeights::Gaussian, 11), std::invalid_argument);
    EXPECT_THROW(pcfWeights(FilterWeights::Gaussian, 0), std::invalid_argument);
}

// The moment blur's half kernel: taps -r..r sum to 1, the ratio of neighbours follows sigma =
// (r + 1) / 2, and it equals the odd PCF Gaussian of 2r + 1 taps where both exist (r <= 4).
TEST(FilterWeightsTest, BlurWeightsAreTheNormalisedHalfGaussian) {
    for (int r = 0; r <= kMaxBlurRadius; ++r) {
        const auto w = blurWeights(r);
        double total = w[0];
        for (int k = 1; k <= r; ++k) total += 2.0 * w[std::size_t(k)];
        EXPECT_NEAR(total, 1.0, 1e-6) << "radius " << r;
        for (int k = r + 1; k <= kMaxBlurRadius; ++k) EXPECT_EQ(w[std::size_t(k)], 0.0f) << "radius " << r;
        const double sigma = 0.5 * (r + 1);
        if (r > 0) EXPECT_NEAR(w[1] / w[0], std::exp(-1.0 / (2.0 * sigma * sigma)), 1e-6) << "radius " << r;
        if (2 * r + 1 <= kMaxFilterTaps) {
            const auto pcf = pcfWeights(FilterWeights::Gaussian, 2 * r + 1);
            for (int k = 0; k <= r; ++k) EXPECT_NEAR(w[std::size_t(k)], pcf[std::size_t(r + k)], 1e-7) << r << " " << k;
        }
    }
    EXPECT_EQ(blurWeights(0)[0], 1.0f);
    EXPECT_THROW(blurWeights(-1), std::invalid_argument);
    EXPECT_THROW(blurWeights(kMaxBlurRadius + 1), std::invalid_argument);
}

// Seed 004's PCF padding: the padded box holds the unpadded one exactly padTexels of its own
// texels in from each x,y side, and depth is untouched.
TEST(FilterWeightsTest, PaddingKeepsTheSliceThatManyTexelsFromTheRim) {
    CameraParams cam;
    SplitParams sp;
    sp.count = 3;
    sp.nearPlane = cam.nearPlane;
    sp.farPlane = cam.farPlane;
    const auto splits = computeSplits(sp);
    const glm::vec3 dir = lightDirection(35.0f, 40.0f);
    for (FitMode fit : {FitMode::Cascade, FitMode::Sphere}) {
        FitParams p;
        p.fit = fit;
        p.mapSize = 256;
        const CascadeFit plain = fitCascade(cam, splits, 1, dir, p);
        p.padTexels = 5;
        const CascadeFit padded = fitCascade(cam, splits, 1, dir, p);
        for (int axis = 0; axis < 2; ++axis) {
            const float texel = padded.lsBox.extent()[axis] / 256.0f;
            EXPECT_NEAR((plain.lsBox.min[axis] - padded.lsBox.min[axis]) / texel, 5.0, 1e-3) << "axis " << axis;
            EXPECT_NEAR((padded.lsBox.max[axis] - plain.lsBox.max[axis]) / texel, 5.0, 1e-3) << "axis " << axis;
        }
        EXPECT_EQ(padded.lsBox.min.z, plain.lsBox.min.z);
        EXPECT_EQ(padded.lsBox.max.z, plain.lsBox.max.z);
        EXPECT_GT(padded.texelWorldSize, plain.texelWorldSize);
    }
    FitParams bad;
    bad.mapSize = 256;
    bad.padTexels = 128;
    EXPECT_THROW(fitCascade(cam, splits, 0, dir, bad), std::invalid_argument);
}

}  // namespace
}  // namespace st::csm
