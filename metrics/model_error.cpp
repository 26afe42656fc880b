#include "metrics/model_error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace st::metrics {

std::vector<double> fractionalRanks(const std::vector<double>& values) {
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<double> ranks(values.size());
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        while (j + 1 < order.size() && values[order[j + 1]] == values[order[i]]) ++j;
        const double shared = (double(i + 1) + double(j + 1)) / 2.0;  // mean of ranks i+1..j+1
        for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = shared;
        i = j + 1;
    }
    return ranks;
}

double spearman(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) throw std::invalid_argument("Spearman: lengths differ");
    if (a.size() < 2) return 0.0;
    const std::vector<double> ra = fractionalRanks(a), rb = fractionalRanks(b);
    const double n = double(a.size());
    const double ma = std::accumulate(ra.begin(), ra.end(), 0.0) / n;
    const double mb = std::accumulate(rb.begin(), rb.end(), 0.0) / n;
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (std::size_t i = 0; i < ra.size(); ++i) {
        sab += (ra[i] - ma) * (rb[i] - mb);
        saa += (ra[i] - ma) * (ra[i] - ma);
        sbb += (rb[i] - mb) * (rb[i] - mb);
    }
    if (saa == 0.0 || sbb == 0.0) return 0.0;
    return sab / std::sqrt(saa * sbb);
}

double medianRelativeError(const std::vector<double>& model, const std::vector<double>& measured) {
    if (model.size() != measured.size()) throw std::invalid_argument("relative error: lengths differ");
    std::vector<double> errors;
    for (std::size_t i = 0; i < model.size(); ++i)
        if (measured[i] > 0.0) errors.push_back(std::abs(model[i] - measured[i]) / measured[i]);
    if (errors.empty()) return 0.0;
    // The true median (mean of the middle two for an even count), unlike cost.h's upper median.
    std::sort(errors.begin(), errors.end());
    const std::size_t n = errors.size();
    return n % 2 ? errors[n / 2] : (errors[n / 2 - 1] + errors[n / 2]) / 2.0;
}

}  // namespace st::metrics
