#include "renderer/csm/filter_weights.h"

#include "renderer/csm/error_text.h"

#include <cmath>

namespace st::csm {

float pcfGaussianSigma(int size) { return 0.5f * float(size / 2 + 1); }

std::array<float, kMaxFilterTaps> pcfWeights(FilterWeights weights, int size) {
    if (size < 1 || size > kMaxFilterTaps || size % 2 == 0)
        fail("filter.size must be odd in 1.." + str(kMaxFilterTaps) + ", got " + str(size));
    std::array<float, kMaxFilterTaps> w{};
    const int r = size / 2;
    const double sigma = pcfGaussianSigma(size);
    double sum = 0.0;
    for (int k = -r; k <= r; ++k) {
        const double v = weights == FilterWeights::Gaussian ? std::exp(-double(k * k) / (2.0 * sigma * sigma)) : 1.0;
        w[static_cast<std::size_t>(k + r)] = static_cast<float>(v);
        sum += v;
    }
    for (int k = 0; k < size; ++k) w[static_cast<std::size_t>(k)] = static_cast<float>(w[static_cast<std::size_t>(k)] / sum);
    return w;
}


std::array<float, kMaxBlurRadius + 1> blurWeights(int radius) {
    if (radius < 0 || radius > kMaxBlurRadius)
        fail("filter.blurRadius must be in 0.." + str(kMaxBlurRadius) + ", got " + str(radius));
    std::array<float, kMaxBlurRadius + 1> w{};
    const double sigma = 0.5 * double(radius + 1);
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) sum += std::exp(-double(k * k) / (2.0 * sigma * sigma));
    for (int k = 0; k <= radius; ++k)
        w[static_cast<std::size_t>(k)] = static_cast<float>(std::exp(-double(k * k) / (2.0 * sigma * sigma)) / sum);
    return w;
}

}  // namespace st::csm
