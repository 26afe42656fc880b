#include "report/pareto.h"

#include <cstddef>

namespace st::report {
namespace {
using Point = std::pair<double, double>;

// Comparisons with NaN are false, so a point with a NaN coordinate dominates nothing and is
// dominated by nothing: it is kept off the front explicitly in paretoFront().
bool dominates(const Point& a, const Point& b) {
    return a.first <= b.first && a.second <= b.second && (a.first < b.first || a.second < b.second);
}

bool hasNaN(const Point& p) { return p.first != p.first || p.second != p.second; }
}  // namespace

// Quadratic: a sweep has hundreds of points, and the pairwise test is the definition itself.
std::vector<bool> paretoFront(const std::vector<std::pair<double, double>>& points) {
    std::vector<bool> front(points.size(), false);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (hasNaN(points[i])) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < points.size() && !dominated; ++j)
            dominated = j != i && dominates(points[j], points[i]);
        front[i] = !dominated;
    }
    return front;
}

}  // namespace st::report
