// The tuner's search on functions whose best point is known: it reaches that point within the
// budget, never evaluates a point twice or past its limit, repeats itself for a seed, and stops
// when asked. No GL: the evaluator is a formula over the settings.
#include "tune/tune_search.h"

#include "tune/tune_explain.h"

#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>

namespace st::tune {
namespace {

// Error falls toward lambda 0.9, slope 0.5, constant 0.01, 3 cascades of 2048; cost grows with
// cascades x texels. The best point within 25 "ms" is therefore known by enumeration.
Evaluation bowl(const Settings& s) {
    Evaluation e;
    e.error = std::pow(s.cascades.lambda - 0.9, 2) + std::pow(s.bias.slope - 0.5, 2) +
              std::pow(s.bias.constant - 0.01, 2) * 100.0 + 1.0 / (s.cascades.count * double(s.cascades.mapSize));
    e.costMs = s.cascades.count * double(s.cascades.mapSize) * s.cascades.mapSize / 1e6 * 2.0;
    e.mapBytes = 4.0 * s.cascades.count * double(s.cascades.mapSize) * s.cascades.mapSize;
    return e;
}

Space smallSpace() {
    Space all = defaultSpace(Settings{});
    Space s;
    for (const char* p : {"cascades.count", "cascades.lambda", "cascades.mapSize", "bias.constant", "bias.slope"})
        s.dims.push_back(*all.find(p));
    return s;
}

// The best of every combination of the space's values within the budget.
Candidate bruteForce(const Space& space, const Budget& budget) {
    Candidate best;
    best.feasible = false;
    std::vector<std::size_t> idx(space.dims.size(), 0);
    while (true) {
        Settings s;
        for (std::size_t d = 0; d < idx.size(); ++d) s = withValue(s, space.dims[d], idx[d]);
        Candidate c{s, bowl(s), "", false};
        c.feasible = budget.fits(c.eval);
        if (c.feasible && (!best.feasible || better(c, best))) best = c;
        std::size_t d = 0;
        while (d < idx.size() && ++idx[d] == space.dims[d].values.size()) idx[d++] = 0;
        if (d == idx.size()) return best;
    }
}

TEST(TuneSearchTest, ReachesTheBestPointWithinTheBudget) {
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 300;
    const Candidate truth = bruteForce(space, opt.budget);
    ASSERT_TRUE(truth.feasible);
    const SearchResult r = search({Settings{}}, space, bowl, opt);
    ASSERT_TRUE(r.best);
    const Candidate& got = r.evaluated[*r.best];
    EXPECT_TRUE(got.feasible);
    EXPECT_LE(got.eval.costMs, 25.0);
    EXPECT_NEAR(got.eval.error, truth.eval.error, 1e-12) << toOrderedJson(got.settings).dump();
    std::size_t grid = 1;
    for (const Dimension& d : space.dims) grid *= d.values.size();
    EXPECT_LT(r.evaluations, int(grid / 10)) << "a walk, not a grid";
}

TEST(TuneSearchTest, EvaluatesEachPointOnceAndNeverPastItsLimit) {
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 17;
    int calls = 0;
    std::set<std::string> seen;
    const SearchResult r = search({Settings{}}, space, [&](const Settings& s) {
        ++calls;
        EXPECT_TRUE(seen.insert(toOrderedJson(s).dump()).second) << "evaluated twice";
        return bowl(s);
    }, opt);
    EXPECT_EQ(calls, 17);
    EXPECT_EQ(r.evaluations, 17);
    EXPECT_FALSE(r.stopped) << "running out of evaluations is not a stop";
}

// A point the space's projection refuses (an engine without such a knob value) is never measured
// nor chosen: measuring it as it stands would score settings the engine cannot take.
TEST(TuneSearchTest, APointTheProjectionRefusesIsNeitherMeasuredNorChosen) {
    Space space = smallSpace();
    space.project = [](const Settings& s) {
        if (s.cascades.count == 3) throw std::invalid_argument("no 3 cascades here");
        return s;
    };
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 60;
    Settings three;
    three.cascades.count = 3;  // a start the projection refuses, as an engine's defaults could be
    const SearchResult r = search({three, Settings{}}, space, [&](const Settings& s) {
        EXPECT_NE(s.cascades.count, 3) << "a refused point was measured";
        return bowl(s);
    }, opt);
    ASSERT_TRUE(r.best.has_value());
    EXPECT_NE(r.evaluated[*r.best].settings.cascades.count, 3);
    const bool refusedSeen = std::any_of(r.evaluated.begin(), r.evaluated.end(), [](const Candidate& c) {
        return c.settings.cascades.count == 3 && !c.eval.valid && c.eval.problem.find("refuses") != std::string::npos;
    });
    EXPECT_TRUE(refusedSeen) << "the refused start is listed as refused, with the projection's reason";
}

TEST(TuneSearchTest, TheSameSeedWalksTheSameWay) {
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 60;
    const SearchResult a = search({Settings{}}, space, bowl, opt);
    const SearchResult b = search({Settings{}}, space, bowl, opt);
    ASSERT_EQ(a.evaluated.size(), b.evaluated.size());
    for (std::size_t i = 0; i < a.evaluated.size(); ++i) EXPECT_EQ(a.evaluated[i].settings, b.evaluated[i].settings) << i;
    opt.seed = 2;
    const SearchResult c = search({Settings{}}, space, bowl, opt);
    bool differs = c.evaluated.size() != a.evaluated.size();
    for (std::size_t i = 0; !differs && i < a.evaluated.size(); ++i) differs = !(a.evaluated[i].settings == c.evaluated[i].settings);
    EXPECT_TRUE(differs) << "another seed walks in another order";
}

TEST(TuneSearchTest, AStartOverTheBudgetWalksBackIntoIt) {
    const Space space = smallSpace();
    Settings start;
    start.cascades.count = 6;
    start.cascades.mapSize = 4096;  // 6 x 4096^2 x 2e-6 = 201 "ms"
    SearchOptions opt;
    opt.budget.ms = 10.0;
    opt.evaluations = 200;
    const SearchResult r = search({start}, space, bowl, opt);
    ASSERT_TRUE(r.best);
    EXPECT_LE(r.evaluated[*r.best].eval.costMs, 10.0);
    EXPECT_FALSE(r.evaluated.front().feasible);
}

Space spaceOf(std::initializer_list<const char*> paths) {
    const Space all = defaultSpace(Settings{});
    Space s;
    for (const char* p : paths) s.dims.push_back(*all.find(p));
    return s;
}

// A search of `space` from `start` where every point costs 1 "ms" of a 2 "ms" budget: only the
// error, `error(s)`, decides.
SearchResult searchByError(const Space& space, const Settings& start, double (*error)(const Settings&), int evaluations) {
    SearchOptions opt;
    opt.budget.ms = 2.0;
    opt.evaluations = evaluations;
    return search({start}, space, [error](const Settings& s) {
        Evaluation e;
        e.error = error(s);
        e.costMs = 1.0;
        return e;
    }, opt);
}

// Map selection alone loses casters (no z-extension), a z-extension alone only costs: together
// they are the best point, which no single move reaches. The coupled move does.
TEST(TuneSearchTest, MapSelectionAndAZExtensionAreTriedTogether) {
    const Space space = spaceOf({"cascades.selection", "cascades.zExtension", "cascades.stabilize"});
    Settings start;
    start.cascades.selection = Selection::Interval;
    start.cascades.zExtension = ZExtension::None;
    const SearchResult r = searchByError(space, start, [](const Settings& s) {
        const bool map = s.cascades.selection == Selection::Map;
        const bool extended = s.cascades.zExtension != ZExtension::None;
        return map ? (extended ? 0.5 : 2.0) : (extended ? 1.1 : 1.0);
    }, 8);
    ASSERT_TRUE(r.best);
    EXPECT_EQ(r.evaluated[*r.best].eval.error, 0.5);
    EXPECT_EQ(r.evaluated[*r.best].move.rfind("cascades.selection interval -> map, cascades.zExtension", 0), 0u)
        << r.evaluated[*r.best].move;
}

// One cascade fewer with the near split kept is the best point; the count dimension alone turns the
// splits practical (the near split moves), and a lambda move does too.
TEST(TuneSearchTest, ACountMoveOnManualSplitsCanKeepThem) {
    const Space space = spaceOf({"cascades.count", "cascades.lambda"});
    Settings start;
    start.cascades.count = 3;
    start.cascades.scheme = SplitScheme::Manual;
    start.cascades.manualSplits = {25.0f, 90.0f};
    const SearchResult r = searchByError(space, start, [](const Settings& s) {
        const bool nearKept = s.cascades.scheme == SplitScheme::Manual && !s.cascades.manualSplits.empty() &&
                              s.cascades.manualSplits.front() == 25.0f;
        return std::abs(s.cascades.count - 2) + (nearKept ? 0.0 : 1.0);
    }, 12);
    ASSERT_TRUE(r.best);
    const Candidate& best = r.evaluated[*r.best];
    EXPECT_EQ(best.eval.error, 0.0);
    EXPECT_EQ(best.settings.cascades.manualSplits, std::vector<float>{25.0f});
    EXPECT_EQ(best.move, "cascades.count 3 -> 2 (manual splits kept)");
}

// Successive halving: a screen that agrees with the full score lets the search skip full
// evaluations of the neighbours that are no better, and it still reaches the best point.
TEST(TuneSearchTest, AScreenSkipsFullEvaluationsOfWorseNeighbours) {
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 300;
    const SearchResult plain = search({Settings{}}, space, bowl, opt);
    int screened = 0;
    opt.screen = [&](const Settings& s) {
        ++screened;
        return bowl(s);
    };
    const SearchResult halving = search({Settings{}}, space, bowl, opt);
    ASSERT_TRUE(plain.best && halving.best);
    EXPECT_DOUBLE_EQ(halving.evaluated[*halving.best].eval.error, plain.evaluated[*plain.best].eval.error);
    EXPECT_GT(halving.screenedOut, 0);
    EXPECT_EQ(halving.screenings, screened);
    EXPECT_LT(halving.evaluationsToBest, plain.evaluationsToBest) << "the screened-out neighbours were not evaluated";
}

// From a start over the budget, cost decides: a neighbour is evaluated in full only when its
// screen models less, so moves that change no cost (the bias) are screened out, not evaluated.
TEST(TuneSearchTest, OverTheBudgetOnlyNeighboursThatScreenCheaperAreEvaluated) {
    const Space space = spaceOf({"bias.slope", "bias.constant", "cascades.mapSize"});
    Settings start;
    start.cascades.count = 4;
    start.cascades.mapSize = 4096;  // 134 "ms" of bowl()
    SearchOptions opt;
    opt.budget.ms = 10.0;
    opt.evaluations = 6;
    std::vector<Settings> full;
    const Evaluator count = [&](const Settings& s) {
        full.push_back(s);
        return bowl(s);
    };
    opt.screen = bowl;
    const SearchResult r = search({start}, space, count, opt);
    ASSERT_TRUE(r.best) << "6 evaluations reach the budget when none is spent on the bias";
    EXPECT_LE(r.evaluated[*r.best].eval.costMs, 10.0);
    EXPECT_GT(r.screenedOut, 0);
    // Every full evaluation after the start, until one fits, is a map-size move down.
    for (std::size_t i = 1; i < full.size() && !(bowl(full[i - 1]).costMs <= 10.0); ++i)
        EXPECT_LT(full[i].cascades.mapSize, full[i - 1].cascades.mapSize) << i;
    // Without the screen's cost test (no screen) the bias moves come first and spend the limit.
    opt.screen = nullptr;
    EXPECT_FALSE(search({start}, space, bowl, opt).best);
}

// A dimension with jumps (the shadow distance) tries every value, the best screened first: the
// best distance, four steps along its list from none, is the first one evaluated in full.
TEST(TuneSearchTest, AJumpDimensionEvaluatesItsBestScreenedValueFirst) {
    Settings start;
    start.camera.farPlane = 1000.0f;
    Space space;
    space.dims.push_back(*defaultSpace(start).find("cascades.shadowDistance"));  // 0, 800, 650, ... 150, 100 m
    ASSERT_TRUE(space.dims.front().jumps);
    auto error = [](const Settings& s) {
        Evaluation e;
        e.error = std::abs((s.cascades.shadowDistance > 0.0f ? s.cascades.shadowDistance : 1000.0f) - 100.0f);
        e.costMs = 1.0;
        return e;
    };
    SearchOptions opt;
    opt.budget.ms = 2.0;
    opt.evaluations = 2;
    opt.screen = error;
    const SearchResult r = search({start}, space, error, opt);
    ASSERT_TRUE(r.best);
    EXPECT_EQ(r.evaluated[*r.best].settings.cascades.shadowDistance, 100.0f);
    EXPECT_EQ(r.evaluated[*r.best].move, "cascades.shadowDistance 0.0 -> 100.0");
    // Without jumps the same two evaluations go one step: 0 -> 800.
    Space plain = space;
    plain.dims.front().jumps = false;
    const SearchResult step = search({start}, plain, error, opt);
    ASSERT_TRUE(step.best);
    EXPECT_EQ(step.evaluated[*step.best].settings.cascades.shadowDistance, 800.0f);
}

// The polish evaluates a settled point's near moves in full, in the screen's order, where the
// walk trusts the screen: here a screen that judges every move worse than the start. The walk
// evaluates none of the bias moves; the polish walks the slope to its best, a step at a time.
TEST(TuneSearchTest, ThePolishEvaluatesNearMovesTheScreenTurnedDown) {
    Settings start;
    start.bias.slope = 1.0f;
    Space space;
    space.dims.push_back(*defaultSpace(start).find("bias.slope"));  // 0, 0.25, 0.5, 0.75, 1, 1.5, 2, 3
    ASSERT_TRUE(space.dims.front().polish);
    auto error = [](const Settings& s) {
        Evaluation e;
        e.error = std::abs(s.bias.slope - 0.5);
        e.costMs = 1.0;
        return e;
    };
    SearchOptions opt;
    opt.budget.ms = 2.0;
    opt.evaluations = 4;
    opt.screen = [&](const Settings& s) {
        Evaluation e = error(s);
        e.error = s == start ? 0.0 : 1.0;
        return e;
    };
    opt.polish = 3;
    const SearchResult r = search({start}, space, error, opt);
    ASSERT_TRUE(r.best);
    EXPECT_EQ(r.evaluated[*r.best].settings.bias.slope, 0.5f);
    EXPECT_EQ(r.evaluated[*r.best].move, "bias.slope 0.75 -> 0.5");
    EXPECT_EQ(r.polished, 3);
    // Without the polish the walk's descent evaluates no slope move: the screen turned each down.
    opt.polish = 0;
    const SearchResult walk = search({start}, space, error, opt);
    EXPECT_EQ(walk.polished, 0);
    for (const Candidate& c : walk.evaluated) EXPECT_EQ(c.move.rfind("bias.slope", 0), std::string::npos) << c.move;
}

// The polish scales the whole range of depths: here the error wants the split at a sixth of the
// shadow distance and the distance at 127.5 m, so from 25 and 150 m any one depth moved alone
// breaks the ratio, and only both scaled by 0.85 together reach the best.
TEST(TuneSearchTest, ThePolishScalesTheSplitsAndTheShadowDistanceTogether) {
    Settings start;
    start.camera.farPlane = 1000.0f;
    start.cascades.count = 2;
    start.cascades.scheme = SplitScheme::Manual;
    start.cascades.manualSplits = {25.0f};
    start.cascades.shadowDistance = 150.0f;
    const Space all = defaultSpace(start);
    Space space;
    for (const char* p : {"cascades.shadowDistance", "cascades.manualSplits[0]"}) space.dims.push_back(*all.find(p));
    auto error = [](const Settings& s) {
        Evaluation e;
        const double d = s.cascades.shadowDistance, split = s.cascades.manualSplits.at(0);
        e.error = std::abs(d - 127.5) + 1000.0 * std::abs(split / d - 1.0 / 6.0);
        e.costMs = 1.0;
        return e;
    };
    SearchOptions opt;
    opt.budget.ms = 2.0;
    opt.evaluations = 8;
    opt.polish = 7;
    opt.screen = error;
    const SearchResult r = search({start}, space, error, opt);
    ASSERT_TRUE(r.best);
    EXPECT_EQ(r.evaluated[*r.best].move, "cascades range x 0.85");
    EXPECT_FLOAT_EQ(r.evaluated[*r.best].settings.cascades.shadowDistance, 127.5f);
    EXPECT_FLOAT_EQ(r.evaluated[*r.best].settings.cascades.manualSplits.at(0), 21.3f);  // 21.25 to a tenth of a metre
}

// The explanation leaves out fields the tuned preset does not read: under manual splits the
// weight lambda is dead, and undoing it would compute the splits again.
TEST(TuneSearchTest, TheExplanationLeavesOutFieldsTheTunedPresetDoesNotRead) {
    Settings input;
    input.cascades.count = 3;
    input.cascades.lambda = 0.75f;
    Settings tuned = input;
    tuned.cascades.scheme = SplitScheme::Manual;
    tuned.cascades.manualSplits = {20.0f, 50.0f};
    tuned.cascades.lambda = 0.5f;
    tuned.bias.slope = 0.5f;
    const Evaluator evaluate = [](const Settings& s) {
        Evaluation e;
        e.error = s.bias.slope;
        e.costMs = 1.0;
        return e;
    };
    const Explanation x = explain(input, evaluate(input), tuned, evaluate(tuned), "soft-filtered", evaluate);
    std::set<std::string> paths;
    for (const Explained& c : x.changes) paths.insert(c.change.path);
    EXPECT_EQ(paths.count("cascades.lambda"), 0u);
    EXPECT_EQ(paths.count("cascades.manualSplits"), 1u);
    EXPECT_EQ(paths.count("bias.slope"), 1u);
}

// Manual splits and the manual scheme are one change: each alone measured nothing (the scheme
// alone computes splits again, the splits alone are not read), so each line said "+0 alone". One
// line now sets both, with the tuned count when the input's has another number of splits, as the
// editor's Apply of that line does; "in the tuned preset" undoes the scheme.
TEST(TuneSearchTest, TheExplanationMeasuresManualSplitsWithTheirSchemeAndCount) {
    Settings input;
    input.cascades.count = 4;
    Settings tuned = input;
    tuned.cascades.count = 3;
    tuned.cascades.scheme = SplitScheme::Manual;
    tuned.cascades.manualSplits = {20.0f, 50.0f};
    const Evaluator evaluate = [](const Settings& s) {
        Evaluation e;
        const bool manual = s.cascades.scheme == SplitScheme::Manual && s.cascades.manualSplits.size() == 2;
        e.error = manual ? std::abs(s.cascades.manualSplits[0] - 20.0) * 0.01 + 0.1 : 0.5;
        e.costMs = s.cascades.count;
        return e;
    };
    const Explanation x = explain(input, evaluate(input), tuned, evaluate(tuned), "soft-filtered", evaluate);
    const Explained* splits = nullptr;
    for (const Explained& c : x.changes) {
        EXPECT_NE(c.change.path, "cascades.scheme") << "the scheme is part of the splits' line";
        if (c.change.path == "cascades.manualSplits") splits = &c;
    }
    ASSERT_NE(splits, nullptr);
    EXPECT_DOUBLE_EQ(splits->alone.error, 0.1) << "the input with the tuned count, scheme and splits";
    EXPECT_DOUBLE_EQ(splits->without.error, 0.5) << "the tuned preset with computed splits";
    ASSERT_EQ(splits->with.size(), 2u);
    EXPECT_EQ(splits->with[0].first, "cascades.count");
    EXPECT_EQ(splits->with[1].second, "manual");
    EXPECT_NE(splits->line.find("20, 50 m (with 3 cascades and the manual scheme)"), std::string::npos) << splits->line;
    EXPECT_EQ(toJson(x)["changes"][std::size_t(splits - x.changes.data())]["with"]["cascades.scheme"], "manual");
}

// Issue 39 #5: an artist's explanation. The change in percent of the error it starts from and of
// the cost, the computed splits named instead of "[]", an artifact the change alone makes worse
// said as a sentence with the line marked, and what the tuned preset has more of than the input.
TEST(TuneSearchTest, TheExplanationSpeaksInPercentAndSaysWhatGetsWorse) {
    Settings input;
    input.cascades.count = 4;
    Settings tuned = input;
    tuned.cascades.scheme = SplitScheme::Manual;
    tuned.cascades.manualSplits = {20.0f, 50.0f, 120.0f};
    tuned.bias.slope = 0.5f;
    const Evaluator evaluate = [&](const Settings& s) {
        Evaluation e;
        const bool manual = s.cascades.scheme == SplitScheme::Manual;
        e.error = (manual ? 0.2 : 0.4) * (s.bias.slope < 1.0f ? 0.5 : 1.0);
        e.costMs = manual ? 9.0 : 10.0;
        e.figures = {{"accuracy.falseShadow", s.bias.slope < 1.0f ? 0.004 : 0.001}};
        if (s.bias.slope < 1.0f && !manual) {
            e.constraintsMet = false;
            e.violated = "acne 0.400 % > 0.100 %";
        }
        return e;
    };
    const Explanation x = explain(input, evaluate(input), tuned, evaluate(tuned), "soft-filtered", evaluate);
    ASSERT_EQ(x.changes.size(), 2u);
    const Explained& splits = x.changes[0].change.path == "cascades.manualSplits" ? x.changes[0] : x.changes[1];
    const Explained& slope = &splits == &x.changes[0] ? x.changes[1] : x.changes[0];
    EXPECT_NE(splits.line.find("(computed) -> 20, 50, 120 m"), std::string::npos) << splits.line;
    EXPECT_NE(splits.line.find("alone it cuts the error by 50 %"), std::string::npos) << splits.line;
    EXPECT_NE(splits.line.find("at 10 % less cost"), std::string::npos) << splits.line;
    EXPECT_EQ(splits.line.rfind("(!) ", 0), std::string::npos) << "nothing got worse with the splits";
    EXPECT_EQ(slope.line.rfind("(!) ", 0), 0u) << slope.line;
    EXPECT_NE(slope.line.find("Alone, acne rises to 0.400 % from the input's 0.100 %."), std::string::npos) << slope.line;
    ASSERT_EQ(x.worse.size(), 1u);
    EXPECT_EQ(x.worse[0], "False shadow rises from 0.1 % to 0.4 % of sun-facing pixels.");
    EXPECT_NE(toMarkdown(x, "t").find("**Worse than the input:** False shadow"), std::string::npos);
}

// A resumed tune asked for more evaluations keeps its first run's screening limit: its walk is
// the shorter one continued (the same points in the same order, then more), so it never ends
// worse. With the limit scaled to the new count the walk screens longer and goes elsewhere.
TEST(TuneSearchTest, ALargerLimitWithTheFirstScreeningLimitContinuesTheWalk) {
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    // A screen that finds three neighbours in four worse than they are: the walk screens many
    // per evaluation and reaches its screening limit early, as real tunes do.
    // Keyed on the space's own values, not the whole preset: a new settings field must not move it.
    opt.screen = [&space](const Settings& s) {
        Evaluation e = bowl(s);
        std::string key = "s1";
        for (const Dimension& d : space.dims) key += currentValue(s, d).dump();
        if (std::hash<std::string>{}(key) % 4 != 0) e.error += 1.0;
        return e;
    };
    opt.evaluations = 10;
    const SearchResult first = search({Settings{}}, space, bowl, opt);
    // At or one over: a comparison screens both points and may pass the limit by the second.
    ASSERT_GE(first.screenings, kScreensPerEvaluation * 10) << "the limit must bind for this test to mean anything";
    const auto prefixOf = [&](const SearchResult& longer) {
        if (longer.evaluated.size() < first.evaluated.size()) return false;
        for (std::size_t i = 0; i < first.evaluated.size(); ++i)
            if (!(longer.evaluated[i].settings == first.evaluated[i].settings)) return false;
        return true;
    };
    opt.evaluations = 40;
    const SearchResult rescaled = search({Settings{}}, space, bowl, opt);
    EXPECT_FALSE(prefixOf(rescaled)) << "with its own screening limit the longer walk is another walk";
    opt.screenings = kScreensPerEvaluation * 10;
    const SearchResult continued = search({Settings{}}, space, bowl, opt);
    EXPECT_TRUE(prefixOf(continued));
    EXPECT_GT(continued.evaluations, first.evaluations);
    ASSERT_TRUE(first.best && continued.best);
    EXPECT_LE(continued.evaluated[*continued.best].eval.error, first.evaluated[*first.best].eval.error);
}

// The second rung also predicts the full cost from the screens' ratio: a neighbour that screens
// better but would land over the budget is not evaluated in full.
TEST(TuneSearchTest, AScreenPredictingACostOverTheBudgetSkipsTheFullEvaluation) {
    Budget budget;
    budget.ms = 100.0;
    Evaluation fromFull, fromScreen, mine;
    fromFull.costMs = 96.0, fromScreen.costMs = 40.0, fromScreen.error = 0.5;
    mine.error = 0.4;
    mine.costMs = 40.0 * 1.03;  // predicted 98.9 ms: within
    EXPECT_TRUE(worthFullEvaluation(mine, fromScreen, fromFull, budget));
    mine.costMs = 40.0 * 1.10;  // predicted 105.6 ms: over the budget by more than the slack
    EXPECT_FALSE(worthFullEvaluation(mine, fromScreen, fromFull, budget));
    mine.costMs = 40.0;
    mine.error = 0.5;  // no better on the screen
    EXPECT_FALSE(worthFullEvaluation(mine, fromScreen, fromFull, budget));
    mine.error = 0.4;
    budget.bytes = 1000.0;
    mine.mapBytes = 1001.0;  // memory is the same at any size
    EXPECT_FALSE(worthFullEvaluation(mine, fromScreen, fromFull, budget));

    // In a search whose screen costs half the full evaluation (a smaller image), no neighbour of a
    // point within the budget is evaluated in full only to be found over it.
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 300;
    opt.screen = [](const Settings& s) {
        Evaluation e = bowl(s);
        e.costMs *= 0.5;
        return e;
    };
    const SearchResult r = search({Settings{}}, space, bowl, opt);
    ASSERT_TRUE(r.best);
    bool within = false;
    int overAfterwards = 0;
    for (const Candidate& c : r.evaluated) {
        if (within && c.move.rfind("restart", 0) != 0 && c.eval.costMs > *opt.budget.ms * (1.0 + kScreenCostSlack))
            ++overAfterwards;
        within = within || c.feasible;
    }
    EXPECT_EQ(overAfterwards, 0);
}

TEST(TuneSearchTest, StopsWhenAskedAndSaysSo) {
    int calls = 0;
    SearchOptions opt;
    opt.evaluations = 100;
    opt.stopRequested = [&] { return calls >= 5; };
    const SearchResult r = search({Settings{}}, smallSpace(), [&](const Settings& s) { ++calls; return bowl(s); }, opt);
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(r.evaluations, 5);
}

// A sharded tune measures a round's neighbours ahead from the plan: the round must try the plan's
// points in its order until one is better than where it stands (then it moves on from there).
TEST(TuneSearchTest, ARoundTriesItsPlanInOrderUntilItMoves) {
    const Space space = smallSpace();
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = 60;
    std::vector<std::vector<std::string>> plans;
    std::vector<std::string> tried;
    std::vector<double> errors;
    opt.plan = [&](const Settings&, const std::vector<Settings>& next) {
        plans.emplace_back();
        for (const Settings& s : next) plans.back().push_back(toOrderedJson(s).dump());
    };
    const Evaluator record = [&](const Settings& s) {
        tried.push_back(toOrderedJson(s).dump());
        errors.push_back(bowl(s).error);
        return bowl(s);
    };
    search({Settings{}}, space, record, opt);
    ASSERT_FALSE(plans.empty());
    const std::vector<std::string>& first = plans.front();
    ASSERT_FALSE(first.empty());
    // tried[0] is the start; the first round follows its plan from tried[1].
    std::size_t n = 0;
    while (n < first.size() && 1 + n < tried.size() && tried[1 + n] == first[n]) {
        ++n;
        if (errors[n] < errors[0]) break;  // the round moves on from the first better neighbour
    }
    ASSERT_GE(n, 1u);
    EXPECT_TRUE(n == first.size() || errors[n] < errors[0])
        << "the round left its plan at neighbour " << n << " of " << first.size() << " without moving";
}

TEST(TuneSearchTest, RefusedSettingsAreNotEvaluated) {
    Space space = smallSpace();
    space.dims.push_back({"cascades.blendBand", {0.0, 0.9}});  // 0.9 is past the field's 0.5 limit
    int calls = 0;
    SearchOptions opt;
    opt.evaluations = 400;
    const SearchResult r = search({Settings{}}, space, [&](const Settings& s) {
        ++calls;
        EXPECT_LE(s.cascades.blendBand, 0.5f);
        return bowl(s);
    }, opt);
    EXPECT_EQ(calls, r.evaluations);
}

// The front descent walks from the best point down to the cheapest settings in rungs, each the
// cheaper move of least error per millisecond saved, then fills the front's widest gaps: with a
// quarter of a grid's evaluations over count, map size and split weight (the shipped sweeps'
// axes), its front is at least as good as the grid's everywhere; the walk alone's stays near the
// budget.
TEST(TuneSearchTest, TheFrontDescentDominatesAGridsFrontWithAQuarterOfItsEvaluations) {
    const Space space = smallSpace();
    std::vector<Evaluation> grid;
    for (int count : {1, 2, 3, 4})
        for (int size : {256, 512, 1024, 2048})
            for (double lambda : {0.5, 0.65, 0.8, 0.95}) {
                Settings g = withFieldJson(withFieldJson(Settings{}, "cascades.count", count), "cascades.mapSize", size);
                grid.push_back(bowl(withFieldJson(g, "cascades.lambda", lambda)));
            }
    SearchOptions opt;
    opt.budget.ms = 25.0;
    opt.evaluations = int(grid.size()) / 4;
    opt.screen = bowl;
    const double floor = bowl(withFieldJson(withFieldJson(Settings{}, "cascades.count", 1), "cascades.mapSize", 256)).costMs;
    const SearchResult without = search({Settings{}}, space, bowl, opt);
    opt.front = opt.evaluations / kFrontShare;
    opt.frontFloorMs = floor;
    const SearchResult with = search({Settings{}}, space, bowl, opt);
    ASSERT_TRUE(with.best);
    EXPECT_GT(with.frontRungs, 0);
    EXPECT_LE(with.evaluations, opt.evaluations);
    const auto undominated = [&](const SearchResult& r) {
        int n = 0;
        for (const Evaluation& g : grid) {
            if (!opt.budget.fits(g)) continue;
            bool onGridFront = true, beaten = false;
            for (const Evaluation& o : grid)
                onGridFront = onGridFront && !(o.costMs <= g.costMs && o.error < g.error);
            for (const Candidate& c : r.evaluated)
                beaten = beaten || (c.eval.valid && opt.budget.fits(c.eval) && c.eval.costMs <= g.costMs && c.eval.error <= g.error);
            n += onGridFront && !beaten;
        }
        return n;
    };
    std::printf("grid front points no evaluated point beats: %d with the descent, %d without (%d evaluations, %d rungs)\n",
                undominated(with), undominated(without), with.evaluations, with.frontRungs);
    EXPECT_EQ(undominated(with), 0);
    EXPECT_GT(undominated(without), 0) << "the walk alone stays near the budget";
}

}  // namespace
}  // namespace st::tune
