#pragma once
// How well modelled costs follow measured ones: the figures scripts/bench_cost_model.sh prints
// and the calibration reports. Plain numerics, no GL.
#include <vector>

namespace st::metrics {

// Ranks 1..n of `values`, ties sharing the mean of the ranks they span (the "fractional" ranking
// Spearman's coefficient needs when values repeat).
std::vector<double> fractionalRanks(const std::vector<double>& values);

// Spearman's rank correlation: Pearson's correlation of the fractional ranks. 0 when either side
// has no spread or fewer than two values. Throws std::invalid_argument when the lengths differ.
double spearman(const std::vector<double>& a, const std::vector<double>& b);

// The median over i of |model[i] - measured[i]| / measured[i], over the samples whose measured
// value is positive (a relative error of a zero measurement is undefined). 0 for none.
double medianRelativeError(const std::vector<double>& model, const std::vector<double>& measured);

}  // namespace st::metrics
