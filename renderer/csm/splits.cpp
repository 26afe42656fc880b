#include "renderer/csm/splits.h"

#include "renderer/csm/error_text.h"
#include "renderer/settings/split_range.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace st::csm {
namespace {

void checkCamera(const SplitParams& p) {
    if (!std::isfinite(p.nearPlane) || p.nearPlane <= 0.0f)
        fail("camera.nearPlane must be > 0, got " + str(p.nearPlane));
    if (!std::isfinite(p.farPlane) || p.nearPlane >= p.farPlane)
        fail("camera.nearPlane (" + str(p.nearPlane) + ") must be less than camera.farPlane (" +
             str(p.farPlane) + ")");
}

void checkShadowDistance(const SplitParams& p) {
    const float d = p.shadowDistance;
    if (d == 0.0f) return;  // 0 = camera far plane
    if (!std::isfinite(d) || d <= p.nearPlane || d > p.farPlane)
        fail("cascades.shadowDistance must be 0 or in (camera.nearPlane, camera.farPlane] = (" +
             str(p.nearPlane) + ", " + str(p.farPlane) + "], got " + str(d));
}

void checkManual(const SplitParams& p, float end) {
    const auto expected = static_cast<std::size_t>(p.count - 1);
    if (p.manual.size() != expected)
        fail("cascades.manualSplits must hold count-1 = " + str(expected) + " values, got " +
             str(p.manual.size()));
    float previous = p.nearPlane;
    for (std::size_t i = 0; i < p.manual.size(); ++i) {
        const float z = p.manual[i];
        if (!(z > previous) || !(z < end))
            fail("cascades.manualSplits[" + str(i) + "] = " + str(z) +
                 " must be increasing and inside (" + str(p.nearPlane) + ", " + str(end) + ")");
        previous = z;
    }
}

void validate(const SplitParams& p, float end) {
    if (p.count < 1 || p.count > kMaxCascades)
        fail("cascades.count must be in 1.." + str(kMaxCascades) + ", got " + str(p.count));
    checkCamera(p);
    checkShadowDistance(p);
    // Lambda and the manual list only matter for their own scheme: don't reject unused values.
    if (p.scheme == SplitScheme::Practical && !(p.lambda >= 0.0f && p.lambda <= 1.0f))
        fail("cascades.lambda must be in [0, 1], got " + str(p.lambda));
    if (p.scheme == SplitScheme::Manual) checkManual(p, end);
}

float lambdaOf(const SplitParams& p) {
    switch (p.scheme) {
        case SplitScheme::Uniform: return 0.0f;
        case SplitScheme::Logarithmic: return 1.0f;
        case SplitScheme::Practical: return p.lambda;
        case SplitScheme::Manual: break;  // the manual list, not lambda, places the splits
    }
    throw std::logic_error("lambdaOf: scheme " + str(static_cast<int>(p.scheme)) + " has no lambda");
}

// Seed 000, practical split scheme: z_i = lambda n (e/n)^(i/N) + (1-lambda)(n + (i/N)(e-n)).
// Evaluated in double so the interior splits are correctly rounded to float.
float practicalSplit(double n, double e, double lambda, int i, int count) {
    const double s = static_cast<double>(i) / count;
    const double logarithmic = n * std::pow(e / n, s);
    const double uniform = n + s * (e - n);
    return static_cast<float>(lambda * logarithmic + (1.0 - lambda) * uniform);
}

}  // namespace

std::vector<float> computeSplits(const SplitParams& p) {
    const float end = splitRangeEnd(p.farPlane, p.shadowDistance);
    validate(p, end);
    std::vector<float> z(static_cast<std::size_t>(p.count) + 1);
    z.front() = p.nearPlane;  // exact end points, not rounded through pow()
    z.back() = end;
    for (int i = 1; i < p.count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        z[k] = p.scheme == SplitScheme::Manual
                   ? p.manual[k - 1]
                   : practicalSplit(p.nearPlane, end, lambdaOf(p), i, p.count);
    }
    return z;
}

}  // namespace st::csm
