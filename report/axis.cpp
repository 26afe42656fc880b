// Axis bounds and ticks (report/chart_frame.h): nice linear steps, log decades with 2 and 5
// between them when the range is short, and a floor for values a log axis cannot show.
#include "report/chart_frame.h"

#include "report/plot_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace st::report::detail {
namespace {

std::string format(double value, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", std::max(decimals, 0), value + 0.0);  // + 0.0: no "-0"
    return buf;
}

// The 1, 2 or 5 times a power of ten nearest `rough` (by ratio).
double niceStep(double rough) {
    double decade = std::pow(10.0, std::floor(std::log10(rough))), best = decade;
    for (double m : {2.0, 5.0, 10.0})
        if (std::abs(std::log(m * decade / rough)) < std::abs(std::log(best / rough))) best = m * decade;
    return best;
}

void linearTicks(Axis& axis) {
    axis.majorStep = niceStep((axis.hi - axis.lo) / 8.0);
    int decimals = int(-std::floor(std::log10(axis.majorStep) + 1e-9));
    for (double v = std::ceil(axis.lo / axis.majorStep - 1e-9) * axis.majorStep; v <= axis.hi + 1e-9 * axis.majorStep;
         v += axis.majorStep)
        axis.ticks.push_back({v, format(std::abs(v) < 1e-12 * axis.majorStep ? 0.0 : v, decimals)});
}

std::string powerLabel(int mantissa, int exponent) {
    if (exponent >= -4 && exponent <= 4) return format(mantissa * std::pow(10.0, exponent), -exponent);
    std::string power = "10#u" + std::to_string(exponent) + "#d";
    return mantissa == 1 ? power : std::to_string(mantissa) + "×" + power;
}

// Short ranges get 2 and 5 (or every mantissa) between the decades, so a log axis always has
// several labels; long ones label every decade, or every second or third.
void logTicks(Axis& axis) {
    double span = axis.hi - axis.lo;
    std::vector<int> mantissas = span > 2.2 ? std::vector<int>{1} : span > 0.9 ? std::vector<int>{1, 2, 5}
                                                                               : std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9};
    int every = span > 16 ? 3 : span > 8 ? 2 : 1;
    for (int e = int(std::floor(axis.lo)); e <= int(std::ceil(axis.hi)); ++e) {
        if (e % every != 0) continue;
        for (int m : mantissas) {
            double w = e + std::log10(double(m));
            if (w >= axis.lo - 1e-9 && w <= axis.hi + 1e-9) axis.ticks.push_back({w, powerLabel(m, e)});
        }
    }
}

void padLinear(Axis& axis, double lo, double hi) {
    double pad = hi > lo ? 0.06 * (hi - lo) : std::max(std::abs(lo) * 0.1, 1.0);
    axis.lo = lo - pad, axis.hi = hi + pad;
    if (lo >= 0 && axis.lo < 0) axis.lo = 0;  // positive data: no negative range
}

void padLog(Axis& axis, double lo, double hi) {
    double span = hi - lo, minSpan = 0.6;  // at least two or three labelled values
    if (span < minSpan) lo -= (minSpan - span) / 2, hi += (minSpan - span) / 2;
    double pad = std::max(0.06 * (hi - lo), 0.05);
    axis.lo = lo - pad, axis.hi = hi + pad;
}
}  // namespace

double Axis::world(double value) const { return log ? std::log10(std::max(value, floor)) : value; }

Axis valueAxis(const std::vector<double>& values, bool log) {
    Axis axis;
    axis.log = log;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, minPositive = lo;
    for (double v : values) {
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v), hi = std::max(hi, v);
        if (v > 0) minPositive = std::min(minPositive, v);
        if (log && v <= 0) ++axis.clamped;
    }
    if (!std::isfinite(lo)) lo = log ? 1.0 : 0.0, hi = log ? 10.0 : 1.0, minPositive = 1.0;
    if (!log) {
        padLinear(axis, lo, hi);
        linearTicks(axis);
        return axis;
    }
    // The floor sits a decade below the smallest positive value, on a power of ten, so clamped
    // points stand apart at the bottom of the axis instead of hiding among real ones.
    if (!std::isfinite(minPositive)) minPositive = 1.0;
    axis.floor = std::pow(10.0, std::floor(std::log10(minPositive)) - (axis.clamped ? 1.0 : 0.0));
    padLog(axis, axis.world(lo), axis.world(hi));
    logTicks(axis);
    return axis;
}

Axis categoryAxis(const std::vector<std::string>& names) {
    Axis axis;
    axis.categorical = true;
    axis.lo = -0.5, axis.hi = double(std::max<std::size_t>(names.size(), 1)) - 0.5;
    axis.majorStep = 1.0;
    for (std::size_t i = 0; i < names.size(); ++i) axis.ticks.push_back({double(i), plText(names[i])});
    return axis;
}

std::string clampNote(const Axis& axis, const char* name) {
    if (axis.clamped == 0) return "";
    return std::to_string(axis.clamped) + (axis.clamped == 1 ? " value" : " values") + " of " + name +
           " ≤ 0 drawn at " + powerLabel(1, int(std::lround(std::log10(axis.floor)))) + " (log axis)";
}

}  // namespace st::report::detail
