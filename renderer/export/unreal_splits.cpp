#include "renderer/export/unreal_splits.h"

#include <algorithm>
#include <cmath>

namespace st::xport {

double accumulatedScale(double exponent, int index, int count) {
    double scale = 1.0, total = 0.0, upTo = 0.0;
    for (int i = 0; i < count; ++i) {
        if (i < index) upTo += scale;
        total += scale;
        scale *= exponent;
    }
    return index <= 0 ? 0.0 : upTo / total;
}

namespace {

double squaredError(double e, const std::vector<double>& fr, int count) {
    double sum = 0.0;
    for (size_t i = 0; i < fr.size(); ++i) {
        const double d = accumulatedScale(e, int(i) + 1, count) - fr[i];
        sum += d * d;
    }
    return sum;
}

double maxError(double e, const std::vector<double>& fr, int count) {
    double worst = 0.0;
    for (size_t i = 0; i < fr.size(); ++i)
        worst = std::max(worst, std::fabs(accumulatedScale(e, int(i) + 1, count) - fr[i]));
    return worst;
}

}  // namespace

ExponentFit fitDistributionExponent(const std::vector<double>& fr, int count) {
    if (fr.empty()) return {};
    double best = 0.05;
    for (double e = 0.05; e <= 20.0; e += 0.01)
        if (squaredError(e, fr, count) < squaredError(best, fr, count)) best = e;
    double lo = std::max(0.05, best - 0.01), hi = best + 0.01;
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int it = 0; it < 60; ++it) {
        const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (squaredError(a, fr, count) < squaredError(b, fr, count))
            hi = b;
        else
            lo = a;
    }
    const double e = 0.5 * (lo + hi);
    return {e, maxError(e, fr, count)};
}

}  // namespace st::xport
