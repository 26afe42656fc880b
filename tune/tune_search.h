#pragma once
// The tuner's search (docs/tuning.md): from the input preset and analytic starting points, a
// seeded coordinate descent over the space's dimensions under a cost budget, with paired moves
// that trade one cost for another at the budget's edge, and seeded restarts from perturbations of
// the best point until the evaluations run out. Not a grid: it walks only where the error falls.
// Pure code: it calls an Evaluator, so tests give it a known function and no GL.
#include "renderer/settings/settings.h"
#include "tune/tune_space.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace st::tune {

struct Evaluation {
    bool valid = true;         // false: the settings were refused (`problem` says why)
    std::string problem;
    double error = 0.0;        // the objective, lower is better (over the tuned views)
    double costMs = 0.0;       // modelled frame cost
    double mapBytes = 0.0;     // shadow and filter map memory
    bool constraintsMet = true;  // the objective's side constraints (artifact classes, flicker)
    std::string violated;        // which, when not met
    nlohmann::ordered_json figures;  // every figure, for the report
};
using Evaluator = std::function<Evaluation(const Settings&)>;

struct Budget {
    std::optional<double> ms;     // modelled cost at most this
    std::optional<double> bytes;  // map memory at most this
    bool fits(const Evaluation& e) const;
    // How far over the budget, as a share of it (0 when within): ranks infeasible points.
    double excess(const Evaluation& e) const;
};

struct Candidate {
    Settings settings;
    Evaluation eval;
    std::string move;  // how the search got here: "start", "bias.slope 1 -> 0.5", ...
    bool feasible = false;
    double excess = 0.0;  // Budget::excess of eval
};

struct SearchProgress {
    int evaluations = 0;  // made so far (cached ones are free and not counted)
    int limit = 0;
    std::optional<std::size_t> best;  // index into `evaluated` of the best feasible point
    const std::vector<Candidate>* evaluated = nullptr;
    std::string trying;   // the move being evaluated
    int screenings = 0;   // first-rung scores so far
};

struct SearchOptions {
    Budget budget;
    int evaluations = 150;
    // Successive halving, two rungs: when set, a neighbour of a point within the budget is first
    // scored by this cheaper evaluator (one view, reduced resolution) and only evaluated in full
    // when it beats the current point there too. Screenings do not count against `evaluations`
    // (at most kScreensPerEvaluation times as many are made).
    Evaluator screen;
    // Screenings at most this many; 0: kScreensPerEvaluation * evaluations. A resumed tune passes
    // its first run's, so a larger `evaluations` continues that walk (its first steps are the
    // same) rather than starting another, which could end worse (docs/tuning.md#running).
    int screenings = 0;
    // Of `evaluations`, this many are kept for the end (every start is measured first in any
    // case): from the best point within the budget,
    // the near moves of each polish dimension (Dimension::polish: shadow distance, split depths,
    // bias, filter parameters, bands), best screened first, each evaluated in full, until none is
    // better (docs/tuning.md#polish). With no point within the budget the walk gets them.
    // kScreensPerPolish screenings per polish evaluation are kept for it.
    int polish = 0;
    // Of `evaluations`, this many are kept for the very end: the front descent
    // (docs/tuning.md#front). From the best point (the lowest error within the budget when no point
    // meets the constraints), each rung takes the cheaper moves its screens rate best, error gained
    // per millisecond saved, until the cost predicted from the screens falls an even share (in
    // ratio) of the way to `frontFloorMs`, and evaluates that point in full; once no cheaper move
    // is left, the rest fill the front's widest gaps in cost. The rungs are judged on the
    // objective alone, as a sweep's front is: cheaper settings rarely keep the artifact classes
    // of a costlier input. kScreensPerFront screenings per front evaluation are kept for it; without
    // a screen there is no descent.
    int front = 0;
    double frontFloorMs = 0.0;  // where the last rung aims: the cheapest settings' modelled cost
    std::uint64_t seed = 1;
    std::function<bool()> stopRequested;  // checked before each evaluation (Ctrl-C)
    std::function<void(const SearchProgress&)> progress;
    // Called at the start of each descent round with the neighbours the round tries, in order, as
    // long as the point stays `from`: a sharded tune measures its share of them ahead, so the
    // shards work in parallel on one round (docs/tuning.md#shards). The search itself is unchanged.
    std::function<void(const Settings& from, const std::vector<Settings>& neighbours)> plan;
};

inline constexpr int kScreensPerEvaluation = 6;
// The share of a tune's evaluations its final polish gets: one in this many (SearchOptions::polish).
inline constexpr int kPolishShare = 4;
// Screenings per polish evaluation: each round ranks every near move of a point (about 60 on
// truck-town), and a polish of 20 evaluations may make several rounds.
inline constexpr int kScreensPerPolish = 20;
// The share of a tune's evaluations `tune --front` keeps for its front descent (SearchOptions::front).
inline constexpr int kFrontShare = 4;
// Screenings per front evaluation: a rung screens every cheaper neighbour (about 40 on truck-town)
// for each of up to kFrontStepsPerRung moves.
inline constexpr int kScreensPerFront = 120;
inline constexpr int kFrontStepsPerRung = 3;
inline constexpr double kFrontMinSaving = 0.01;
// A front rung also tries the whole range of depths scaled by these (rangeMoves).
inline constexpr double kFrontRangeScales[] = {0.6, 0.8};
// The polish also scales the whole range of depths (shadow distance and manual splits) by these.
inline constexpr double kRangeScales[] = {0.8, 0.85, 0.9, 0.95, 1.05, 1.1, 1.2};

// The second rung's rule: a neighbour screened as `mine`, of a point `from` within the budget
// (evaluated in full as `fromFull`, screened as `fromScreen`), is worth a full evaluation when it
// screens better and its full cost, predicted from the screens' ratio, stays within the budget:
// modelled cost times mine.costMs / fromScreen.costMs at most kScreenCostSlack over the budget's
// milliseconds, and map memory (the same at any output size) within its bytes. Without these
// tests, map-size moves up from a point at the budget's edge screened better (bigger maps are)
// and spent a full evaluation each to learn they were over the budget: 22 of 60 evaluations of
// truck-town's tune at ogldev-49's budget, every one of them over its memory.
inline constexpr double kScreenCostSlack = 0.03;
bool worthFullEvaluation(const Evaluation& mine, const Evaluation& fromScreen, const Evaluation& fromFull,
                         const Budget& budget);
// Its cost tests alone: the full cost predicted from the screens within the budget.
bool fitsOnScreen(const Evaluation& mine, const Evaluation& fromScreen, const Evaluation& fromFull, const Budget& budget);

// Outside the budget, the first rung's rule: a neighbour is worth a full evaluation when its
// screen models less time or less map memory than the point's own screen.
bool cheaperOnScreen(const Evaluation& mine, const Evaluation& fromScreen);

struct SearchResult {
    std::vector<Candidate> evaluated;  // every distinct point, in the order first evaluated
    std::optional<std::size_t> best;   // the best feasible, if any
    int evaluations = 0;
    int screenings = 0;                // cheap first-rung scores (SearchOptions::screen)
    int screenedOut = 0;               // of them, candidates not worth a full evaluation
    int evaluationsToBest = 0;         // full evaluations made when the best point was found
    int polished = 0;                  // evaluations the final polish made (SearchOptions::polish)
    int frontRungs = 0;                // points the front descent evaluated (SearchOptions::front)
    bool stopped = false;              // by stopRequested
};

// The indices of the candidates `member` keeps that no other kept one beats in both modelled cost
// and error (report::paretoFront), cheapest first; of equal points, the first.
std::vector<std::size_t> costErrorFront(const std::vector<Candidate>& points,
                                        const std::function<bool(const Candidate&)>& member);

// a is better than b: feasible before infeasible; among feasible, lower error, then lower cost;
// among infeasible, less over the budget.
bool better(const Candidate& a, const Candidate& b);

// Searches from `starts` (the first is the input preset). The evaluator is called at most
// opt.evaluations times and never twice for equal settings.
SearchResult search(const std::vector<Settings>& starts, const Space& space, const Evaluator& evaluate,
                    const SearchOptions& opt);

}  // namespace st::tune
