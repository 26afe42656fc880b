#pragma once
// The tuner's one run (tune_run.h's runTune), split into rooms named for what each does:
// tune_run.cpp (the run: starts, search, simplify), tune_budget.cpp (references and budget),
// tune_measure.cpp (measurements: the journal and the other shards), tune_folder.cpp (the run's
// folder and resume, and the text of figures), tune_starts.cpp (where the search starts),
// tune_outputs.cpp (progress, tuned.json, the engine's text, front/), tune_summary.cpp
// (summary.json). Internal to tune/.
#include "tune/tune_run.h"

#include "metrics/measure_session.h"
#include "tune/tune_eval.h"
#include "tune/tune_journal.h"
#include "tune/tune_search.h"
#include "tune/tune_views.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::tune::detail {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

inline constexpr int kTuneVersion = 1;

inline constexpr double kMiB = 1024.0 * 1024.0;

inline constexpr const char* kFlickerKey = "flicker.flipRate";

// What earlier runs of the tune in `dir` left in progress.json (nothing for a new folder; a
// progress file is rewritten whole, so an unreadable one only loses these):
// - seconds: their wall-clock ("secondsAllRuns"), so a resumed tune's time is theirs plus its own;
// - screeningLimit: the first run's ("screeningLimit", or kScreensPerEvaluation times the "limit"
//   of a folder written before it was kept; 0 for none). A resumed run keeps it, so its walk is
//   the first run's continued (SearchOptions::screenings).
struct EarlierRuns {
    double seconds = 0.0;
    int screeningLimit = 0;
};

// Ctrl-C while waiting for another shard's measurement.
struct StoppedWhileWaiting {};

// tune_folder.cpp
std::string fixed(double v, int decimals);

std::string errorText(const std::string& choice, double raw);

std::string budgetText(const Budget& b);

// The folder belongs to one tune: the same preset, objective, budget, views, seed and profile.
// More evaluations may be asked of a resumed tune.
void claimFolder(const fs::path& dir, const Json& identity);

EarlierRuns earlierRuns(const fs::path& dir);

// tune_starts.cpp
// The cheapest settings of the space on the input's scene: if they miss the budget, nothing fits.
Settings cheapest(Settings s);

// Analytic biases, in texel units rather than metres, so they hold at any texel size: a slope
// of 1 texel per unit of tan with half a texel of normal offset; or seed 004's receiver-plane
// depth (the receiver's own slope across the texel) with a margin of half a texel of slope and
// nothing else (with none, the receiver's depth at the texel centre ties with the stored depth of
// the same surface and rounding decides: 30 % acne on truck-town). The descent did not reach the
// second by itself: on truck-town at ogldev-49's budget it tuned the bias in metres per cascade
// first, and from there the receiver plane alone scored worse (soft error 0.00913 against 0.00884).
Settings texelBias(Settings s);
Settings planeBias(Settings s);

// A method's maps placed on what the views show (SDSM, Lauritzen, Salvi and Lefohn 2011): light
// boxes fitted to the visible samples, each pixel reading the finest map that holds it, and the
// casters toward the light that a sample-tight box would cut drawn by a fixed reach (a tenth of
// the far plane), not the whole scene column; with the receiver-plane bias, which needs no trade
// between acne and light leaks. On truck-town this start is what takes ogldev-49's maps from
// 0.852 % to 0.464 % misclassified at less than its cost; the descent did not get there by single
// moves, as each alone either loses casters (the sample fit alone: 3.7 %) or costs more.
Settings seenBy(Settings s);

// The same with the splits' range cut to that tenth of the far plane where it reaches further:
// most of what a view shows is near (truck-town's preset camera: half its covered pixels within
// 22 m, 95 % within 98 m, 98 % within 304 m of its 1500 m far plane), so its maps' texels go
// there. On truck-town at ogldev-49's budget the tune from it ends at 0.403 % misclassified
// against 0.438 % without it (soft filtered 0.005284 against 0.005485).
Settings seenNear(Settings s);

// Analytic starting points: splits from the depth range the camera actually sees (depth bounds:
// SDSM), a light box fitted to the visible samples, and each analytic bias.
std::vector<Settings> starts(const Settings& input);

// The first rung of the search's successive halving: half the output size, each side.
Settings screenSize(Settings s);

void widenLimits(Objective& o, const std::vector<std::pair<std::string, double>>& more);

class Tuner {
public:
    explicit Tuner(const TuneOptions& opt) : opt_(opt) {}

    TuneOutcome run();

private:
    TuneOutcome tune(std::chrono::steady_clock::time_point t0);

    // The tuned preset a finished earlier run left in the folder (nothing for a new or an
    // interrupted one, so a resumed tune still ends where an uninterrupted one does). A run
    // continued with more evaluations walks elsewhere than the one it continues once the polish's
    // share moves (a tune of 40 polishes from its 30th evaluation, one of 160 from its 120th), and
    // did end worse: living-room as soft-shadows-blog 0.0024 -> 0.0181 soft filtered.
    std::optional<Settings> earlierTuned() const;

    // The earlier run's tuned preset becomes the result when it is better than the search's best
    // (its measurement is in the journal: free), so a continued tune never ends worse.
    void keepIfBetter(const Settings& earlier);

    void say(const std::string& line) const;

    // The journaled measurement of `s` on `views`, or a new one (journaled at once).
    // A sharded tune waits for the shard that owns `s` unless `waitForOwner` is false.
    Evaluation measured(const Settings& s, const std::string& views, bool waitForOwner = true);

    bool writes() const { return opt_.shard.index == 1; }

    // The measurement of a point another shard owns, once it is in that shard's journal; nothing
    // when this shard owns it, or when the others fell silent (then this shard measures it).
    std::optional<Evaluation> fromAnotherShard(const Settings& s, const std::string& views, bool wait);

    // A sharded round's plan: the neighbours the search will try from `from`, in its order. While
    // this shard waits for another's measurement, it measures what it owns of the next few
    // neighbours, as the search would (screened first when `from` is within the budget); every
    // search then finds them in the journals. The window bounds the work spent on a round the
    // search leaves early (its first better neighbour ends it).
    void plan(const Settings& from, std::vector<Settings> next);

    bool owned(const Settings& s, const std::string& views) const;

    // One measurement ahead of `waitedFor` in the plan: true when it made one.
    bool measureAhead(const Settings& waitedFor);

    // The flicker limit: the largest F of the references, or the input's own with none.
    double flickerLimit(const Evaluation& input);

    void references();

    Json identity() const;

    // --budget-ms / --budget-mib as given; --budget-from: the cheapest reference's modelled cost
    // and memory on the input's scene and tuned views.
    void resolveBudget();

    void progress(const SearchProgress& p);

    Json pointJson(const Evaluation& e) const;

    // progress.json: what a UI draws while the tune runs (docs/tuning.md#progress). Evaluations
    // within the budget and the constraints are "feasible"; the input and the references are
    // measured before the search starts, so they are there from the first write.
    void writeProgress(const std::string& stage, int done, int limit, const std::vector<Candidate>* evaluated);

    Json evalJson(const Evaluation& e) const;

    // The tuned preset without the changes that buy nothing: a change whose removal keeps the point
    // within the budget and the constraints at no more error and no more cost is undone (a
    // restart's random moves ride along otherwise). These are the evaluations the explanation's
    // "in the tuned preset" needs anyway.
    void simplify(std::size_t best);

    // <engine>.json: the knobs (engine-check --knobs takes its "knobs"); the paste-ready text beside.
    void writeEngineOutputs(xport::Engine e, const Settings& best) const;

    void writeOutputs(const Candidate& best, double seconds);

    // Every evaluated point (and the input and references) as a sweep's results: the Pareto charts
    // of modelled cost and memory against the objective, and the front's presets.
    // A point front/ charts: within the budget and the constraints; with --front, within the
    // budget (the descent's rungs are judged on the objective alone).
    bool onFront(const Candidate& c) const { return c.feasible || (opt_.front && c.eval.valid && budget_.fits(c.eval)); }

    // The points of front/ that no other is better than in both cost and error, cheapest first.
    std::vector<const Candidate*> frontPoints() const;

    Json frontJson() const;

    void sayFront() const;

    void writeFront(const Candidate* best);

    void writeSummary(const Candidate& best, const Evaluation& inputEval, double seconds);

    const TuneOptions& opt_;
    Settings input_;
    fs::path presetDir_;
    std::vector<View> views_;
    std::vector<std::pair<std::string, Settings>> refs_;
    std::vector<std::pair<std::string, Settings>> compared_;  // --compare-with: drawn, never a budget
    metrics::MeasureSession session_;
    std::optional<Journal> journal_;
    std::optional<ViewEvaluator> evaluator_;
    std::optional<ViewEvaluator> screener_;  // the first rung: the preset camera at half size
    Budget budget_;
    Objective objective_;
    SearchResult result_;
    int made_ = 0, resumed_ = 0, fromShards_ = 0;
    bool keptEarlier_ = false;  // the result is the folder's earlier tuned.json (keepIfBetter)
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    double earlierSeconds_ = 0.0;  // of the runs this one resumed
    int screeningLimit_ = 0;       // the first run's (earlierRuns)
    double secondsAllRuns() const;
    bool othersSilent_ = false;  // a shard wrote nothing in opt_.shardWaitSeconds
    Settings planFrom_;           // the search's current round (plan())
    std::vector<Settings> plan_;
    std::vector<double> evalMs_;    // wall-clock of each new evaluation on the tuned or held-out views
    std::vector<double> screenMs_;  // ... of each new screening (the preset camera at half size)
};

}  // namespace st::tune::detail
