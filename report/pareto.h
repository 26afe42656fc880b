#pragma once
// The Pareto front of points that minimise both coordinates (docs/architecture.md "Speed vs
// accuracy"): a point dominates another when it is no worse in both and strictly better in one;
// the front is the set no point dominates.
#include <utility>
#include <vector>

namespace st::report {

// front[i] is true when no point dominates points[i]. Equal points are all on the front.
// NaN coordinates never dominate and are never on the front.
std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points);

}  // namespace st::report
