#include "metrics/texel_density.h"

#include <algorithm>
#include <cmath>

namespace st::metrics {
namespace {

double quantile(const std::vector<float>& sorted, double q) {
    const auto rank = std::size_t(std::ceil(q * double(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

double shareWhere(const std::vector<float>& values, auto predicate) {
    return double(std::count_if(values.begin(), values.end(), predicate)) / double(values.size());
}

}  // namespace

DensityStats densityStats(std::vector<float> values) {
    DensityStats d;
    d.pixels = values.size();
    if (values.empty()) return d;
    std::sort(values.begin(), values.end());
    d.median = quantile(values, 0.5);
    d.p90 = quantile(values, 0.9);
    d.p95 = quantile(values, 0.95);
    d.max = values.back();
    d.aliasingShare = shareWhere(values, [](float v) { return v > kAliasingAbove; });
    d.wastedShare = shareWhere(values, [](float v) { return v < kWastedBelow; });
    return d;
}

DensityReport texelDensity(const MeasureSamples& s, int cascadeCount) {
    std::vector<float> all;
    std::vector<std::vector<float>> perCascade(std::size_t(std::max(cascadeCount, 0)));
    for (std::size_t i = 0; i < s.size(); ++i) {
        const int c = s.cascade(i);
        if (!s.covered(i) || c < 0 || c >= cascadeCount) continue;
        all.push_back(s.shadow[i].w);
        perCascade[std::size_t(c)].push_back(s.shadow[i].w);
    }
    DensityReport r;
    r.all = densityStats(std::move(all));
    for (auto& values : perCascade) r.cascades.push_back(densityStats(std::move(values)));
    return r;
}

}  // namespace st::metrics
