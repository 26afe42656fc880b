#include "tune/tune_search.h"

#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "report/pareto.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <tuple>

namespace st::tune {
namespace {

// `s` with d's j-th value, or nothing when the field refuses it.
std::optional<Settings> tryValue(const Settings& s, const Dimension& d, std::size_t j) {
    try {
        return withValue(s, d, j);
    } catch (const SettingsError&) {
        return std::nullopt;
    }
}

std::string text(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// Dimensions that trade cost against each other at the budget's edge: one up, another down.
constexpr const char* kCostDims[] = {"cascades.count", "cascades.mapSize", "cascades.shadowDistance"};

// A cascade fewer or more on manual splits, the others kept where they are (a count move alone
// computes every split again from lambda): fewer drops the farthest split, more puts one at the
// geometric middle of the last slice. Nothing when the scheme is not manual.
std::vector<std::pair<std::string, Settings>> manualCountMoves(const Settings& base) {
    std::vector<std::pair<std::string, Settings>> out;
    const CascadeSettings& c = base.cascades;
    if (c.scheme != SplitScheme::Manual || c.manualSplits.size() != std::size_t(c.count - 1)) return out;
    const float end = c.shadowDistance > 0.0f ? std::min(c.shadowDistance, base.camera.farPlane) : base.camera.farPlane;
    for (int delta : {-1, 1}) {
        std::vector<float> splits = c.manualSplits;
        if (delta < 0 && splits.empty()) continue;
        if (delta < 0) splits.pop_back();
        else splits.push_back(std::sqrt((splits.empty() ? base.camera.nearPlane : splits.back()) * end));
        try {
            Settings s = withFieldJson(base, "cascades.count", c.count + delta);
            s.cascades.scheme = SplitScheme::Manual;
            s.cascades.manualSplits = splits;
            out.emplace_back("cascades.count " + std::to_string(c.count) + " -> " + std::to_string(c.count + delta) +
                                 " (manual splits kept)",
                             std::move(s));
        } catch (const SettingsError&) {
        }
    }
    return out;
}

class Walker {
public:
    Walker(const Space& space, const Evaluator& evaluate, const SearchOptions& opt)
        : space_(space), evaluate_(evaluate), opt_(opt), rng_(opt.seed) {}

    // The index of `s` among the evaluated points, evaluating it if new; nullopt once the
    // evaluations are spent or a stop was requested.
    std::optional<std::size_t> visit(const Settings& given, const std::string& move) {
        const auto [s, refused] = projected(given);
        const std::string key = toOrderedJson(s).dump();
        if (const auto it = seen_.find(key); it != seen_.end()) return it->second;
        Candidate c{s, {}, move, false};
        if (const std::vector<std::string> problems = validate(s); !problems.empty() || !refused.empty()) {
            c.eval.valid = false;
            c.eval.problem = refused.empty() ? problems.front() : refused;
        } else {
            if (out_.evaluations >= cap_) return std::nullopt;
            if (opt_.stopRequested && opt_.stopRequested()) {
                out_.stopped = true;
                return std::nullopt;
            }
            report(move);
            c.eval = evaluate_(s);
            ++out_.evaluations;
            ++fresh_;
        }
        c.feasible = c.eval.valid && c.eval.constraintsMet && opt_.budget.fits(c.eval);
        c.excess = opt_.budget.excess(c.eval);
        out_.evaluated.push_back(std::move(c));
        const std::size_t i = out_.evaluated.size() - 1;
        seen_.emplace(key, i);
        if (out_.evaluated[i].feasible && (!out_.best || better(out_.evaluated[i], out_.evaluated[*out_.best]))) {
            out_.best = i;
            out_.evaluationsToBest = out_.evaluations;
        }
        return i;
    }

    // Whether `s` is worth a full evaluation from the point `cur`: without a screen always; from a
    // point over the budget when it screens cheaper (cost decides there: a bias move, which
    // changes no cost, spent 11 of 16 evaluations of the README's tune of the yard at 10 ms);
    // else when it screens better than `cur`. Always once the screenings are spent.
    bool worthEvaluating(const Settings& s, std::size_t cur) {
        if (!opt_.screen) return true;
        if (!at(cur).feasible && at(cur).excess <= 0.0) return true;  // a constraint, not the budget: error decides
        if (out_.screenings >= screeningLimit()) return true;
        const std::optional<Evaluation> mine = screened(s), theirs = screened(at(cur).settings);
        if (!mine || !theirs) return true;
        const bool worth = at(cur).feasible ? worthFullEvaluation(*mine, *theirs, at(cur).eval, opt_.budget)
                                            : cheaperOnScreen(*mine, *theirs);
        if (!worth) ++out_.screenedOut;
        return worth;
    }

    // The screen of `s` (none: settings the validator or the screen refuses).
    std::optional<Evaluation> screened(const Settings& given) {
        const auto [s, refused] = projected(given);
        const std::string key = toOrderedJson(s).dump();
        if (const auto it = screens_.find(key); it != screens_.end()) return it->second;
        if (!refused.empty() || !validate(s).empty()) return std::nullopt;
        if (opt_.stopRequested && opt_.stopRequested()) return std::nullopt;  // visit() stops the search next
        Evaluation e = opt_.screen(s);
        ++out_.screenings;
        const std::optional<Evaluation> valid = e.valid ? std::optional<Evaluation>(std::move(e)) : std::nullopt;
        screens_.emplace(key, valid);
        return valid;
    }

    SearchResult run(const std::vector<Settings>& starts) {
        const int front = std::clamp(opt_.front, 0, opt_.evaluations);
        const int searchCap = opt_.evaluations - front;
        const int polish = std::clamp(opt_.polish, 0, searchCap);
        cap_ = opt_.evaluations;  // every start is measured, then the walk leaves the polish and the front their shares
        screenCap_ = std::max(0, totalScreenings() - kScreensPerEvaluation * (polish + front));
        std::optional<std::size_t> cur = walk(starts, std::nullopt, searchCap - polish);
        if (!out_.stopped && polish > 0) {
            cap_ = std::max(searchCap, out_.evaluations);
            screenCap_ = totalScreenings() - kScreensPerEvaluation * front + (kScreensPerPolish - kScreensPerEvaluation) * polish;
            if (out_.best) {
                const int before = out_.evaluations;
                polishFrom(*out_.best);
                out_.polished = out_.evaluations - before;
            } else {  // nothing to polish: the walk goes on from the point nearest the budget
                if (!cur)
                    for (std::size_t i = 0; i < out_.evaluated.size(); ++i)
                        if (!cur || better(at(i), at(*cur))) cur = i;
                if (cur) walk({}, cur, cap_);
            }
        }
        if (out_.stopped || front == 0) return finish();
        cap_ = opt_.evaluations;
        screenCap_ = totalScreenings() + (kScreensPerPolish - kScreensPerEvaluation) * polish +
                     (kScreensPerFront - kScreensPerEvaluation) * front;
        if (const std::optional<std::size_t> from = frontStart()) descendFront(*from);
        return finish();
    }

private:
    // The starts, then descent rounds, paired and coupled moves and restarts from `cur`, until
    // `cap` evaluations are made (or more, when the starts took them), a stop is requested or 20
    // restarts find nothing new. Returns the point it was at (nothing once it ran out).
    std::optional<std::size_t> walk(const std::vector<Settings>& starts, std::optional<std::size_t> cur, int cap) {
        for (const Settings& s : starts) {
            const auto i = visit(s, cur ? "analytic start" : "start");
            if (!i) return std::nullopt;
            if (!cur || better(at(*i), at(*cur))) cur = i;
        }
        cap_ = std::max(cap, out_.evaluations);
        int idleRestarts = 0;
        while (cur && idleRestarts < 20) {
            const int before = fresh_;
            std::optional<std::size_t> next = descend(*cur, false);
            if (!next) return std::nullopt;
            if (*next == *cur) next = descend(*cur, true);
            if (!next) return std::nullopt;
            if (*next == *cur) next = pairMove(*cur);
            if (!next) return std::nullopt;
            if (*next == *cur) next = coupledMove(*cur);
            if (!next) return std::nullopt;
            if (*next == *cur) {
                next = restart();
                if (!next) return std::nullopt;
                // A restart outside the budget would spend a descent walking back (every step a full
                // evaluation: cost, not error, decides there); try another from the best instead.
                if (!at(*next).feasible && out_.best) next = out_.best;
            }
            cur = next;
            idleRestarts = fresh_ == before ? idleRestarts + 1 : 0;
        }
        return cur;
    }

    // From the best point: the whole range of depths scaled (rangeMoves), then its polish
    // dimensions' near moves (one and two steps), each group best screened first, each move
    // evaluated in full: these moves change the error by a few tenths of a percent, less than a
    // screen (one view at half size) resolves, so it ranks them but does not reject them. The
    // range goes first: ranked with the rest, bias moves worth a hundredth of what it buys came
    // first and took the round. The first better point is taken and its moves tried next, until
    // none is better or the evaluations are spent.
    void polishFrom(std::size_t cur) {
        for (;;) {
            const Settings& base = at(cur).settings;
            std::vector<std::size_t> order;
            for (std::size_t i = 0; i < space_.dims.size(); ++i)
                if (space_.dims[i].polish) order.push_back(i);
            std::shuffle(order.begin(), order.end(), rng_);
            std::vector<std::pair<std::string, Settings>> range, near;
            for (auto& [move, s] : rangeMoves(base, kRangeScales))
                if (!seen(s) && validate(s).empty()) range.emplace_back(std::move(move), std::move(s));
            for (std::size_t di : order)
                for (auto& [j, s] : moves(base, space_.dims[di]))
                    if (!seen(s) && validate(s).empty()) near.emplace_back(moveText(base, space_.dims[di], j), std::move(s));
            if (opt_.plan) {
                std::vector<Settings> next;
                for (const auto* group : {&range, &near})
                    for (const auto& t : *group) next.push_back(t.second);
                opt_.plan(base, next);
            }
            std::vector<std::pair<std::string, Settings>> tries = screenedWithinBudget(std::move(range), cur);
            for (auto& t : screenedWithinBudget(std::move(near), cur)) tries.push_back(std::move(t));
            std::optional<std::size_t> next = cur;
            for (auto& [move, s] : tries) {
                next = visit(s, move);
                if (!next) return;
                if (better(at(*next), at(cur))) break;
            }
            if (*next == cur || !better(at(*next), at(cur))) return;
            cur = *next;
        }
    }

    // Where the front descent starts: the best point; without one (no point within the budget
    // meets the constraints), the lowest error within the budget; else the point least over it.
    std::optional<std::size_t> frontStart() const {
        if (out_.best) return out_.best;
        // Within the budget before over it; then the lower error, or the smaller excess.
        const auto rank = [this](const Candidate& c) {
            const bool fits = opt_.budget.fits(c.eval);
            return std::make_tuple(!fits, fits ? c.eval.error : c.excess);
        };
        std::optional<std::size_t> from;
        for (std::size_t i = 0; i < out_.evaluated.size(); ++i)
            if (at(i).eval.valid && (!from || rank(at(i)) < rank(at(*from)))) from = i;
        return from;
    }

    // The front descent (SearchOptions::front): each rung aims an even share (in ratio) of the way
    // from the point it is at down to frontFloorMs (rung()), and the descent goes on from the point it
    // reached when that costs less in full. Once no cheaper move is left, the evaluations that
    // remain fill the front's widest gaps in cost: a rung from the costlier point of the gap aims
    // at its middle.
    void descendFront(std::size_t cur) {
        if (!opt_.screen) return;  // its moves are chosen on screens
        bool bottom = false;
        std::set<std::size_t> spent;  // gap tops no rung leads down from any more
        while (out_.evaluations < cap_) {
            // An even share of the way in ratio: a cost range may span orders of magnitude.
            const double here = at(cur).eval.costMs, left = double(cap_ - out_.evaluations);
            double aim = opt_.frontFloorMs > 0.0 && here > opt_.frontFloorMs ? here * std::pow(opt_.frontFloorMs / here, 1.0 / left)
                                                                             : here - (here - opt_.frontFloorMs) / left;
            if (bottom) {
                const std::optional<std::pair<std::size_t, double>> gap = widestGap(spent);
                if (!gap) return;
                std::tie(cur, aim) = *gap;
            }
            const Rung r = rung(cur, aim);
            if (r.stopped) return;
            if (!r.reached) {
                if (bottom) spent.insert(cur);
                bottom = true;
                continue;
            }
            // Not cheaper in full (the screens' cost ratio misled): the next rung tries another
            // move from here, as this one is now seen.
            if (!bottom && at(*r.reached).eval.valid && at(*r.reached).eval.costMs < at(cur).eval.costMs) cur = *r.reached;
        }
    }

    struct Rung {
        std::optional<std::size_t> reached;  // the point evaluated; none: no new cheaper move
        bool stopped = false;                // the evaluations ran out or a stop was requested
    };

    // From `cur`, up to kFrontStepsPerRung moves not yet evaluated, each saving at least
    // kFrontMinSaving of its screened cost (ties of no error change among tiny savings took rungs
    // that moved nowhere) and gaining the least error per millisecond saved on its screen (a
    // cheaper and better move first), until the full cost predicted from the screens reaches
    // `aim`; then that point evaluated in full.
    Rung rung(std::size_t cur, double aim) {
        const Candidate here = at(cur);
        const std::optional<Evaluation> hereScreen = screened(here.settings);
        if (!hereScreen || hereScreen->costMs <= 0.0) return {};
        Settings s = here.settings;
        Evaluation sScreen = *hereScreen;
        std::string move;
        for (int step = 0; step < kFrontStepsPerRung; ++step) {
            std::optional<std::pair<std::string, Settings>> pick;
            Evaluation pickScreen;
            double bestSlope = INFINITY, bestSaving = 0.0;
            for (auto& [text, t] : cheaperMoves(s)) {
                if (out_.screenings >= screeningLimit()) break;
                if (seen(t)) continue;
                const std::optional<Evaluation> e = screened(t);
                const double saving = e ? sScreen.costMs - e->costMs : 0.0;
                if (saving < kFrontMinSaving * hereScreen->costMs) continue;
                const double slope = (e->error - sScreen.error) / saving;
                if (slope < bestSlope || (slope == bestSlope && saving > bestSaving)) {
                    bestSlope = slope;
                    bestSaving = saving;
                    pick.emplace(std::move(text), std::move(t));
                    pickScreen = *e;
                }
            }
            if (!pick) break;
            move += (move.empty() ? "" : ", ") + pick->first;
            s = std::move(pick->second);
            sScreen = pickScreen;
            if (here.eval.costMs * sScreen.costMs / hereScreen->costMs <= aim) break;
        }
        if (s == here.settings || seen(s)) return {};
        const std::optional<std::size_t> k = visit(s, "front: " + move);
        if (!k) return {std::nullopt, true};
        ++out_.frontRungs;
        return {k, false};
    }

    // The front's points (valid, within the budget, no other both cheaper and better), cheapest
    // first; of each two neighbours the widest apart in cost whose costlier one is not `spent`:
    // that one and the middle cost.
    std::optional<std::pair<std::size_t, double>> widestGap(const std::set<std::size_t>& spent) const {
        const std::vector<std::size_t> front =
            costErrorFront(out_.evaluated, [this](const Candidate& c) { return c.eval.valid && opt_.budget.fits(c.eval); });
        std::optional<std::pair<std::size_t, double>> widest;
        double width = 0.0;
        for (std::size_t n = 1; n < front.size(); ++n) {
            const double lo = at(front[n - 1]).eval.costMs, hi = at(front[n]).eval.costMs;
            if (spent.count(front[n]) || hi - lo <= width) continue;
            width = hi - lo;
            widest.emplace(front[n], 0.5 * (lo + hi));
        }
        return widest;
    }

    // The moves a front rung tries from `base`: one step along every dimension that may change
    // the cost (bias does not), a cascade fewer on manual splits, and the range of depths nearer
    // (kFrontRangeScales); the screens keep the cheaper ones.
    std::vector<std::pair<std::string, Settings>> cheaperMoves(const Settings& base) const {
        std::vector<std::pair<std::string, Settings>> out = rangeMoves(base, kFrontRangeScales);
        for (auto& [text, s] : manualCountMoves(base))
            if (s.cascades.count < base.cascades.count) out.emplace_back(std::move(text), std::move(s));
        for (const Dimension& d : space_.dims) {
            if (d.path.rfind("bias.", 0) == 0) continue;
            const std::size_t i = currentIndex(base, d);
            for (auto& [j, s] : moves(base, d))
                if (j + 1 == i || j == i + 1) out.emplace_back(moveText(base, d, j), std::move(s));
        }
        std::vector<std::pair<std::string, Settings>> valid;
        for (auto& t : out)
            if (validate(t.second).empty()) valid.push_back(std::move(t));
        return valid;
    }

    // The whole range of depths nearer or farther by a few percent (kRangeScales): the shadow
    // distance and every manual split together, so each slice keeps its share. Finer than the
    // depths' ladders (22.5, 30 m; 120, 150 m on truck-town): there the walk's splits of 25 and
    // 60 m and distance of 150 m scaled by 0.85 read 0.3965 % misclassified against 0.4025 %
    // (soft filtered 0.005156 against 0.005284).
    template <std::size_t N>
    static std::vector<std::pair<std::string, Settings>> rangeMoves(const Settings& base, const double (&scales)[N]) {
        std::vector<std::pair<std::string, Settings>> out;
        const CascadeSettings& c = base.cascades;
        const bool manual = c.scheme == SplitScheme::Manual && !c.manualSplits.empty();
        if (c.shadowDistance <= 0.0f && !manual) return out;
        const auto scaled = [](float v, double f) { return float(std::round(double(v) * f * 10.0) / 10.0); };
        for (double f : scales) {
            Settings s = base;
            if (s.cascades.shadowDistance > 0.0f) s.cascades.shadowDistance = scaled(s.cascades.shadowDistance, f);
            if (manual)
                for (float& split : s.cascades.manualSplits) split = scaled(split, f);
            char text[64];
            std::snprintf(text, sizeof text, "cascades range x %.2f", f);
            if (!(s == base)) out.emplace_back(text, std::move(s));
        }
        return out;
    }

    // `tries` from the point `cur` within the budget, best screened first, without those whose
    // screen predicts a cost over the budget (worthFullEvaluation's cost tests); as they are once
    // the screenings are spent.
    std::vector<std::pair<std::string, Settings>> screenedWithinBudget(std::vector<std::pair<std::string, Settings>> tries,
                                                                        std::size_t cur) {
        const std::optional<Evaluation> theirs = opt_.screen ? screened(at(cur).settings) : std::nullopt;
        if (!theirs || out_.screenings + int(tries.size()) > screeningLimit()) return tries;
        std::vector<std::pair<double, std::size_t>> ranked;
        for (std::size_t k = 0; k < tries.size(); ++k) {
            const std::optional<Evaluation> e = screened(tries[k].second);
            if (!e || !fitsOnScreen(*e, *theirs, at(cur).eval, opt_.budget)) {
                ++out_.screenedOut;
                continue;
            }
            ranked.emplace_back(e->error, k);
        }
        std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<std::pair<std::string, Settings>> out;
        for (const auto& [error, k] : ranked) out.push_back(std::move(tries[k]));
        return out;
    }

    const Candidate& at(std::size_t i) const { return out_.evaluated[i]; }
    int totalScreenings() const { return opt_.screenings > 0 ? opt_.screenings : kScreensPerEvaluation * opt_.evaluations; }
    int screeningLimit() const { return screenCap_; }
    bool seen(const Settings& s) const { return seen_.count(toOrderedJson(onto(s)).dump()) != 0; }

    // `s` projected onto the space (an engine's knobs), and why the projection refused it, if it
    // did: such a point stays as it is and is not measured (it is not what the engine would take).
    struct Projected {
        Settings settings;
        std::string refused;
    };
    Projected projected(const Settings& s) const {
        if (!space_.project) return {s, ""};
        try {
            return {space_.project(s), ""};
        } catch (const std::exception& e) {
            return {s, std::string("the space's projection refuses it: ") + e.what()};
        }
    }
    Settings onto(const Settings& s) const { return projected(s).settings; }

    void report(const std::string& trying) {
        if (!opt_.progress) return;
        opt_.progress({out_.evaluations, opt_.evaluations, out_.best, &out_.evaluated, trying, out_.screenings});
    }

    std::string moveText(const Settings& from, const Dimension& d, std::size_t j) const {
        return d.path + " " + text(currentValue(from, d)) + " -> " + text(d.values[j]);
    }

    // One round over the dimensions (the refinements, or the others) in a seeded order; the first
    // neighbour better than the current point is taken. Returns the point reached (== cur when
    // nothing was better).
    std::optional<std::size_t> descend(std::size_t cur, bool refinements) {
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < space_.dims.size(); ++i)
            if (space_.dims[i].refinement == refinements) order.push_back(i);
        std::shuffle(order.begin(), order.end(), rng_);
        if (opt_.plan) opt_.plan(at(cur).settings, neighbours(at(cur).settings, order, at(cur).feasible));
        for (std::size_t di : order) {
            const Dimension& d = space_.dims[di];
            const Settings base = at(cur).settings;
            // Jumps only where screens decide which to evaluate: from a point over the budget every
            // move is a full evaluation, and a far value rarely walks back into it.
            const bool jumps = d.jumps && at(cur).feasible;
            for (const auto& [j, s] : jumps ? bestScreenedFirst(moves(base, d, true)) : moves(base, d)) {
                if (!seen(s) && !worthEvaluating(s, cur)) continue;
                const auto k = visit(s, moveText(base, d, j));
                if (!k) return std::nullopt;
                if (better(at(*k), at(cur))) {
                    cur = *k;
                    break;
                }
            }
        }
        return cur;
    }

    // The neighbours descend() tries from `base`, in its order, that are new and valid.
    std::vector<Settings> neighbours(const Settings& base, const std::vector<std::size_t>& order, bool feasible) const {
        std::vector<Settings> out;
        for (std::size_t di : order)
            for (auto& [j, s] : moves(base, space_.dims[di], space_.dims[di].jumps && feasible))
                if (!seen(s) && validate(s).empty()) out.push_back(std::move(s));
        return out;
    }

    // A dimension's moves from `base`, nearest first: one step up, down, then two (with `jumps`,
    // every value, nearest first).
    static std::vector<std::pair<std::size_t, Settings>> moves(const Settings& base, const Dimension& d, bool jumps = false) {
        std::vector<std::pair<std::size_t, Settings>> out;
        if (!applies(base, d.path)) return out;
        const long i = long(currentIndex(base, d));
        std::vector<long> deltas{1L, -1L, 2L, -2L};
        if (jumps)
            for (long delta = 3; delta < long(d.values.size()); ++delta) deltas.insert(deltas.end(), {delta, -delta});
        for (long delta : deltas) {
            const long j = i + delta;
            if (j < 0 || j >= long(d.values.size())) continue;
            if (std::optional<Settings> s = tryValue(base, d, std::size_t(j)); s && !(*s == base))
                out.emplace_back(std::size_t(j), std::move(*s));
        }
        return out;
    }

    // `moves` ordered by their screens, best first (stable: unscreened ones keep their order,
    // last); as they are, once the screenings are spent.
    std::vector<std::pair<std::size_t, Settings>> bestScreenedFirst(std::vector<std::pair<std::size_t, Settings>> moves) {
        if (!opt_.screen || out_.screenings + int(moves.size()) > screeningLimit()) return moves;
        std::vector<double> error;
        for (const auto& [j, s] : moves) {
            const std::optional<Evaluation> e = screened(s);
            error.push_back(e ? e->error : INFINITY);
        }
        std::vector<std::size_t> order(moves.size());
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return error[a] < error[b]; });
        std::vector<std::pair<std::size_t, Settings>> out;
        for (std::size_t k : order) out.push_back(std::move(moves[k]));
        return out;
    }

    // At the budget's edge no single move helps: one cost dimension up and another down.
    std::optional<std::size_t> pairMove(std::size_t cur) {
        for (const char* up : kCostDims) {
            for (const char* down : kCostDims) {
                const Dimension* du = space_.find(up);
                const Dimension* dd = space_.find(down);
                if (up == down || !du || !dd) continue;
                const Settings base = at(cur).settings;
                const std::size_t iu = currentIndex(base, *du), id = currentIndex(base, *dd);
                if (iu + 1 >= du->values.size() || id == 0) continue;
                const std::optional<Settings> mid = tryValue(base, *du, iu + 1);
                const std::optional<Settings> s = mid ? tryValue(*mid, *dd, id - 1) : std::nullopt;
                if (!s || *s == base || (!seen(*s) && !worthEvaluating(*s, cur))) continue;
                const auto k = visit(*s, moveText(base, *du, iu + 1) + ", " + moveText(*mid, *dd, id - 1));
                if (!k) return std::nullopt;
                if (better(at(*k), at(cur))) return k;
            }
        }
        return cur;
    }

    // Moves that pay only together, when no single or cost-paired move helps: map selection reads
    // a cascade's box past its split, where casters beyond the slice's depth are missing unless
    // the box reaches toward the sun (the z-extension); and a cascade fewer or more on manual
    // splits (manualCountMoves). Each is screened first, like a descent's neighbour.
    std::optional<std::size_t> coupledMove(std::size_t cur) {
        const Settings base = at(cur).settings;
        std::vector<std::pair<std::string, Settings>> tries = manualCountMoves(base);
        const Dimension* selection = space_.find("cascades.selection");
        const Dimension* extension = space_.find("cascades.zExtension");
        if (selection && extension)
            for (auto& [j, mid] : moves(base, *selection))
                for (std::size_t k = 0; k < extension->values.size(); ++k)
                    if (std::optional<Settings> s = tryValue(mid, *extension, k); s && !(*s == mid))
                        tries.emplace_back(moveText(base, *selection, j) + ", " + moveText(mid, *extension, k), std::move(*s));
        for (auto& [move, s] : tries) {
            if (!seen(s) && !worthEvaluating(s, cur)) continue;
            const auto k = visit(s, move);
            if (!k) return std::nullopt;
            if (better(at(*k), at(cur))) return k;
        }
        return cur;
    }

    // A seeded perturbation of the best point (three random moves): the descent goes on from there.
    std::optional<std::size_t> restart() {
        const std::size_t from = out_.best ? *out_.best : 0;
        Settings s = at(from).settings;
        std::string move = "restart:";
        for (int n = 0; n < 3; ++n) {
            const Dimension& d = space_.dims[std::uniform_int_distribution<std::size_t>(0, space_.dims.size() - 1)(rng_)];
            const std::size_t j = std::uniform_int_distribution<std::size_t>(0, d.values.size() - 1)(rng_);
            if (const std::optional<Settings> next = tryValue(s, d, j)) {
                move += " " + moveText(s, d, j);
                s = *next;
            }
        }
        return visit(s, move);
    }

    SearchResult finish() { return std::move(out_); }

    const Space& space_;
    const Evaluator& evaluate_;
    const SearchOptions& opt_;
    std::mt19937_64 rng_;
    std::map<std::string, std::size_t> seen_;
    std::map<std::string, std::optional<Evaluation>> screens_;  // settings -> screen (none: invalid)
    SearchResult out_;
    int cap_ = 0;        // evaluations the current phase may reach (the walk's, then all)
    int screenCap_ = 0;  // screenings likewise
    int fresh_ = 0;  // evaluations made (restarts that found only known points do not count)
};

}  // namespace

bool worthFullEvaluation(const Evaluation& mine, const Evaluation& fromScreen, const Evaluation& fromFull,
                         const Budget& budget) {
    return mine.error < fromScreen.error && fitsOnScreen(mine, fromScreen, fromFull, budget);
}

bool fitsOnScreen(const Evaluation& mine, const Evaluation& fromScreen, const Evaluation& fromFull, const Budget& budget) {
    if (budget.bytes && mine.mapBytes > *budget.bytes) return false;
    if (budget.ms && fromScreen.costMs > 0.0) {
        const double predicted = fromFull.costMs * mine.costMs / fromScreen.costMs;
        if (predicted > *budget.ms * (1.0 + kScreenCostSlack)) return false;
    }
    return true;
}

bool cheaperOnScreen(const Evaluation& mine, const Evaluation& fromScreen) {
    return mine.costMs < fromScreen.costMs || mine.mapBytes < fromScreen.mapBytes;
}

bool Budget::fits(const Evaluation& e) const {
    return (!ms || e.costMs <= *ms) && (!bytes || e.mapBytes <= *bytes);
}

double Budget::excess(const Evaluation& e) const {
    double over = 0.0;
    if (ms && *ms > 0.0) over += std::max(0.0, e.costMs / *ms - 1.0);
    if (bytes && *bytes > 0.0) over += std::max(0.0, e.mapBytes / *bytes - 1.0);
    return over;
}

bool better(const Candidate& a, const Candidate& b) {
    if (a.feasible != b.feasible) return a.feasible;
    if (!a.eval.valid || !b.eval.valid) return a.eval.valid && !b.eval.valid;
    if (!a.feasible) {
        // Both over the budget or breaking a constraint: closer to feasible first.
        if (a.eval.constraintsMet != b.eval.constraintsMet) return a.eval.constraintsMet;
        if (a.excess != b.excess) return a.excess < b.excess;
        return a.eval.error < b.eval.error;
    }
    if (a.eval.error != b.eval.error) return a.eval.error < b.eval.error;
    return a.eval.costMs < b.eval.costMs;
}

std::vector<std::size_t> costErrorFront(const std::vector<Candidate>& points,
                                        const std::function<bool(const Candidate&)>& member) {
    std::vector<std::pair<double, double>> xy;
    for (const Candidate& c : points)
        xy.emplace_back(member(c) ? c.eval.costMs : NAN, member(c) ? c.eval.error : NAN);  // NaN: never on it
    const std::vector<bool> on = report::paretoFront(xy);
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (on[i] && std::none_of(out.begin(), out.end(), [&](std::size_t j) { return xy[j] == xy[i]; })) out.push_back(i);
    std::stable_sort(out.begin(), out.end(), [&](std::size_t a, std::size_t b) { return xy[a].first < xy[b].first; });
    return out;
}

SearchResult search(const std::vector<Settings>& starts, const Space& space, const Evaluator& evaluate,
                    const SearchOptions& opt) {
    return Walker(space, evaluate, opt).run(starts);
}

}  // namespace st::tune
