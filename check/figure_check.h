#pragma once
// Figure tolerances of a check suite, read against the figures table (metrics/figure_table.h),
// which knows each figure's unit and which way is better. A figure is held to the golden's value
// ("no worse than the golden + 0.05 pp", "no worse than the golden x 1.1") or to a bound
// ("max": 0 for flicker F). No GL.
#include "metrics/figure_table.h"

#include <optional>
#include <string>

namespace st::check {

enum class FigureRule {
    Max,                 // value <= limit
    Min,                 // value >= limit
    WorseByAtMost,       // worse than the golden by at most `limit`, in the raw unit
    WorseByAtMostPp,     // a share, worse by at most `limit` percentage points
    WorseByAtMostFactor  // lower-is-better: <= golden x limit; higher-is-better: >= golden / limit
};

struct FigureTolerance {
    const metrics::FigureRow* row = nullptr;
    FigureRule rule = FigureRule::Max;
    double limit = 0.0;
    std::string describe() const;  // "worse by at most 0.05 pp", "at most 0 %"
};

// The suite's JSON key of a rule ("worse_by_at_most_pp"), and the rule of a key.
const char* ruleKey(FigureRule r);
std::optional<FigureRule> ruleOfKey(const std::string& key);

// The figure a suite names: its key ("accuracy.misclassified"), its sweep choice ("flicker"),
// its key as one camel-case word ("softFilteredError") or its key's last part when that is
// unique ("misclassified"). Throws std::invalid_argument naming what went wrong.
const metrics::FigureRow& figureNamed(const std::string& name);
// Why `rule` cannot apply to `row` ("flicker F is a share..."), or "" when it can.
std::string ruleProblem(const metrics::FigureRow& row, FigureRule rule, double limit);

struct FigureVerdict {
    const metrics::FigureRow* row = nullptr;
    std::string rule;                     // FigureTolerance::describe()
    std::optional<double> golden, actual; // raw values
    bool pass = false;
    std::string message;  // "misclassified 1.234 % vs golden 1.100 % (+0.134 pp), allowed worse by at most 0.05 pp"
};

FigureVerdict checkFigure(const FigureTolerance& t, std::optional<double> golden, std::optional<double> actual);

}  // namespace st::check
