#include "check/figure_check.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace st::check {
namespace {
using metrics::Better;
using metrics::FigureRow;
using metrics::FigureUnit;

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// "soft.penumbraWidth.absErrorPx" -> "softPenumbraWidthAbsErrorPx"
std::string camelKey(const std::string& key) {
    std::string out;
    bool upper = false;
    for (char c : key) {
        if (c == '.') {
            upper = true;
            continue;
        }
        out += upper ? char(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    return out;
}

std::string lastPart(const std::string& key) { return key.substr(key.rfind('.') + 1); }

// How much worse `actual` is than `golden`, in the raw unit (positive: worse).
double worseBy(Better b, double golden, double actual) { return b == Better::Higher ? golden - actual : actual - golden; }

bool within(const FigureTolerance& t, double golden, double actual) {
    // A hair of slack for values that went through JSON text and back.
    const double eps = 1e-12 * std::max({1.0, std::abs(golden), std::abs(actual)});
    switch (t.rule) {
        case FigureRule::Max: return actual <= t.limit + eps;
        case FigureRule::Min: return actual >= t.limit - eps;
        case FigureRule::WorseByAtMost: return worseBy(t.row->better, golden, actual) <= t.limit + eps;
        case FigureRule::WorseByAtMostPp: return worseBy(t.row->better, golden, actual) * 100.0 <= t.limit + eps;
        case FigureRule::WorseByAtMostFactor:
            return t.row->better == Better::Higher ? actual * t.limit >= golden - eps : actual <= golden * t.limit + eps;
    }
    return false;
}

bool needsGolden(FigureRule r) { return r != FigureRule::Max && r != FigureRule::Min; }
}  // namespace

const char* ruleKey(FigureRule r) {
    switch (r) {
        case FigureRule::Max: return "max";
        case FigureRule::Min: return "min";
        case FigureRule::WorseByAtMost: return "worse_by_at_most";
        case FigureRule::WorseByAtMostPp: return "worse_by_at_most_pp";
        case FigureRule::WorseByAtMostFactor: return "worse_by_at_most_factor";
    }
    return "";
}

std::optional<FigureRule> ruleOfKey(const std::string& key) {
    for (FigureRule r : {FigureRule::Max, FigureRule::Min, FigureRule::WorseByAtMost, FigureRule::WorseByAtMostPp,
                         FigureRule::WorseByAtMostFactor})
        if (key == ruleKey(r)) return r;
    return std::nullopt;
}

std::string FigureTolerance::describe() const {
    const FigureUnit u = row ? row->unit : FigureUnit::Count;
    switch (rule) {
        case FigureRule::Max: return "at most " + metrics::formatValue(u, limit);
        case FigureRule::Min: return "at least " + metrics::formatValue(u, limit);
        case FigureRule::WorseByAtMost: return "worse than the golden by at most " + number(limit) + " (raw)";
        case FigureRule::WorseByAtMostPp: return "worse than the golden by at most " + number(limit) + " pp";
        case FigureRule::WorseByAtMostFactor: return "worse than the golden by at most a factor " + number(limit);
    }
    return "";
}

const FigureRow& figureNamed(const std::string& name) {
    const auto& table = metrics::figureTable();
    if (const FigureRow* r = metrics::findFigure(name)) return *r;
    for (const FigureRow& r : table)
        if ((!r.choice.empty() && r.choice == name) || camelKey(r.key) == name) return r;
    std::vector<const FigureRow*> byLast;
    for (const FigureRow& r : table)
        if (lastPart(r.key) == name) byLast.push_back(&r);
    if (byLast.size() == 1) return *byLast.front();
    if (byLast.size() > 1) {
        std::string keys;
        for (const FigureRow* r : byLast) keys += (keys.empty() ? "" : ", ") + r->key;
        throw std::invalid_argument("'" + name + "' names more than one figure (" + keys + "); give the key");
    }
    throw std::invalid_argument("'" + name + "' is not a figure (docs/metrics.md lists them, e.g. "
                                "accuracy.misclassified, flicker, softFilteredError)");
}

std::string ruleProblem(const FigureRow& row, FigureRule rule, double limit) {
    if (!std::isfinite(limit)) return "the limit must be a finite number";
    if (row.timing) return row.key + " is a measured time that differs between runs; it cannot be checked";
    if (needsGolden(rule) && row.better == Better::None)
        return row.key + " has no better direction (docs/metrics.md); use max or min";
    if (rule == FigureRule::WorseByAtMostPp && row.unit != FigureUnit::Share)
        return row.key + " is not a share; worse_by_at_most_pp applies to shares only";
    if (needsGolden(rule) && limit < 0.0) return "the allowance must be >= 0";
    if (rule == FigureRule::WorseByAtMostFactor && limit < 1.0) return "the factor must be >= 1";
    return "";
}

FigureVerdict checkFigure(const FigureTolerance& t, std::optional<double> golden, std::optional<double> actual) {
    FigureVerdict v{t.row, t.describe(), golden, actual, false, ""};
    const FigureUnit u = t.row->unit;
    std::string text = t.row->label + " " + metrics::formatValue(u, actual) + " vs golden " +
                       metrics::formatValue(u, golden);
    if (golden && actual) text += " (" + metrics::formatDelta(u, *actual - *golden) + ")";
    if (!actual && !golden) {
        v.pass = true;
        v.message = text + ": measured by neither";
        return v;
    }
    if (!actual) {
        v.message = text + ": not measured now";
        return v;
    }
    if (needsGolden(t.rule) && !golden) {
        v.message = text + ": the golden has no value";
        return v;
    }
    v.pass = within(t, golden.value_or(0.0), *actual);
    v.message = text + (v.pass ? ", within: " : ", allowed: ") + v.rule;
    return v;
}

}  // namespace st::check
