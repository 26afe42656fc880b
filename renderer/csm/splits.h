#pragma once
// Split distances along the view axis. Pure functions, view depths in metres.
#include "renderer/settings/settings.h"

#include <span>
#include <vector>

namespace st::csm {

struct SplitParams {
    SplitScheme scheme = SplitScheme::Practical;
    int count = 4;                 // number of cascades N, 1..kMaxCascades (settings.h)
    float nearPlane = 0.1f;        // camera near n, > 0
    float farPlane = 400.0f;       // camera far f, > n
    float lambda = 0.5f;           // practical blend, [0,1]; 1 = logarithmic, 0 = uniform
    std::span<const float> manual; // N-1 interior ends (Manual only), strictly increasing in (n, end)
    float shadowDistance = 0.0f;   // 0 = f; else shadows end here (seed 001), n < d <= f
};

// Returns N+1 view depths z_0 = n < z_1 < ... < z_N = end, where end = shadowDistance or f.
// Practical (seed 000, eq. for z_i): z_i = lambda n (e/n)^(i/N) + (1-lambda)(n + (i/N)(e-n)),
// with e the end distance. Uniform is lambda = 0, Logarithmic lambda = 1.
// Throws std::invalid_argument naming the bad parameter (count out of 1..kMaxCascades, n <= 0, n >= f,
// lambda outside [0,1], manual list of the wrong length or not increasing, shadowDistance
// outside (n, f]).
std::vector<float> computeSplits(const SplitParams& p);

}  // namespace st::csm
