#pragma once
// The 1-D tap weights of the NxN PCF kernel (seed 004: "create a kernel (such as a Gaussian) for an
// N x N grid. The weights must add up to 1"). The shader weights tap (x, y) by w[x] w[y], so the
// 2-D kernel is separable and sums to 1 when w does. Uploaded as is (CascadeBlock::pcfWeights).
#include "renderer/settings/settings.h"

#include <array>

namespace st::csm {

inline constexpr int kMaxFilterTaps = 9;  // filter.size's maximum

// Weights of taps -r..r (r = size/2) at indices 0..size-1, the rest 0; normalised to sum 1.
// Box: 1/size each. Gaussian: exp(-k^2 / (2 sigma^2)) with sigma = (r + 1) / 2 texels, so the
// outermost tap keeps a weight of exp(-2 r^2/(r+1)^2) (0.61 for 3x3, 0.28 for 9x9) of the centre's
// and the kernel still reaches its full width.
std::array<float, kMaxFilterTaps> pcfWeights(FilterWeights weights, int size);

// sigma of the Gaussian weights for `size` taps, texels.
float pcfGaussianSigma(int size);

inline constexpr int kMaxBlurRadius = 16;  // filter.blurRadius's maximum

// The moment blur's 1-D Gaussian (renderer/render/moment_maps.h): taps -r..r with the PCF rule
// sigma = (r + 1) / 2 texels, normalised over the 2r + 1 taps. Symmetric, so only |k| = 0..r is
// kept (index |k|, the rest 0): the shaders fetch one weight per tap instead of recomputing the
// Gaussian and its sum at every tap (CascadeBlock::blurWeights).
std::array<float, kMaxBlurRadius + 1> blurWeights(int radius);

}  // namespace st::csm
