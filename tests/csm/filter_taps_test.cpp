// Taps per shaded fragment against kernels counted by hand from shaders/shadow_sampling.glsl.
#include "renderer/csm/filter_taps.h"

#include <gtest/gtest.h>

namespace st::csm {
namespace {

FilterSettings kind(FilterKind k) {
    FilterSettings f;
    f.kind = k;
    return f;
}

TEST(FilterTaps, HardIsOneNearestTexel) {
    const FilterTaps t = filterTapsPerFragment(kind(FilterKind::Hard), false);
    EXPECT_EQ(t.taps, 1);
    EXPECT_EQ(t.texels, 1);
    EXPECT_EQ(t.bytesPerTexel, 4);
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Hard), true).taps, 1);  // one compare either way
}

TEST(FilterTaps, Pcf2x2IsOneBilinearCompareOrFourNearestWithReceiverPlane) {
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Pcf2x2), false).taps, 1);
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Pcf2x2), false).texels, 4);
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Pcf2x2), true).taps, 4);
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Pcf2x2), true).texels, 4);
}

TEST(FilterTaps, PcfNxNIsNSquaredBilinearTaps) {
    FilterSettings f = kind(FilterKind::PcfNxN);
    f.size = 5;  // x, y in -2..2: 25 taps of 2x2 texels
    EXPECT_EQ(filterTapsPerFragment(f, false).taps, 25);
    EXPECT_EQ(filterTapsPerFragment(f, false).texels, 100);
    EXPECT_EQ(filterTapsPerFragment(f, true).taps, 100);
    f.size = 9;
    EXPECT_EQ(filterTapsPerFragment(f, false).taps, 81);
    f.weights = FilterWeights::Gaussian;  // weights change the sum, not the taps
    EXPECT_EQ(filterTapsPerFragment(f, false).taps, 81);
}

TEST(FilterTaps, PcssIsTheBlockerSearchThenTheFilter) {
    FilterSettings f = kind(FilterKind::Pcss);
    f.blockerTaps = 5;  // 25 raw reads
    f.size = 3;         // then 9 bilinear compares
    const FilterTaps t = filterTapsPerFragment(f, false);
    EXPECT_EQ(t.taps, 25 + 9);
    EXPECT_EQ(t.texels, 25 + 36);
    EXPECT_EQ(t.bytesPerTexel, 4);
    EXPECT_EQ(filterTapsPerFragment(f, true).taps, 25 + 36);
}

TEST(FilterTaps, MomentFiltersFetchOnceFromTheirFormat) {
    FilterSettings f = kind(FilterKind::Vsm);
    f.blurRadius = 4;  // the blur is the filter passes' work, not the fragment's
    EXPECT_EQ(filterTapsPerFragment(f, false).taps, 1);
    EXPECT_EQ(filterTapsPerFragment(f, false).texels, 4);
    EXPECT_EQ(filterTapsPerFragment(f, false).bytesPerTexel, 8);  // RG32F
    f.mipmaps = true;
    EXPECT_EQ(filterTapsPerFragment(f, false).texels, 8);  // trilinear: two levels
    f.moments16 = true;
    EXPECT_EQ(filterTapsPerFragment(f, false).bytesPerTexel, 4);  // RG16F
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Evsm4), false).bytesPerTexel, 16);
    EXPECT_EQ(filterTapsPerFragment(kind(FilterKind::Msm), false).bytesPerTexel, 16);
    EXPECT_EQ(momentBytesPerTexel(FilterKind::Msm, true), 8);  // RGBA16
    EXPECT_EQ(momentBytesPerTexel(FilterKind::Pcf2x2, false), 0);
}

}  // namespace
}  // namespace st::csm
