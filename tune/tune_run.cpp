#include "tune/tune_run.h"

#include "renderer/export/engine_snippets.h"
#include "tune/tune_engine.h"

#include "metrics/cost.h"
#include "metrics/figure_table.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"
#include "tune/tune_eval.h"
#include "tune/tune_explain.h"
#include "tune/tune_holdout.h"
#include "tune/tune_journal.h"
#include "tune/tune_views.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

namespace st::tune {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
namespace {

constexpr int kTuneVersion = 1;
constexpr double kMiB = 1024.0 * 1024.0;

std::string fixed(double v, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

std::string errorText(const std::string& choice, double raw) {
    const metrics::FigureRow& row = sweep::errorFigure(choice);
    const metrics::UnitInfo& u = metrics::unitInfo(row.unit);
    char text[48];
    std::snprintf(text, sizeof text, "%.4g", raw * u.scale);  // errors span 1e-5 .. 1: significant digits
    return text + (u.symbol[0] ? " " + std::string(u.symbol) : "");
}

std::string budgetText(const Budget& b) {
    std::string t;
    if (b.ms) t += fixed(*b.ms, 1) + " ms";
    if (b.bytes) t += (t.empty() ? "" : " and ") + fixed(*b.bytes / kMiB, 1) + " MiB";
    return t;
}

// The folder belongs to one tune: the same preset, objective, budget, views, seed and profile.
// More evaluations may be asked of a resumed tune.
void claimFolder(const fs::path& dir, const Json& identity) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": cannot create output folder: " + (ec ? ec.message() : "not a directory"));
    const fs::path file = dir / "tune.json";
    if (std::ifstream in(file); in) {
        Json there;
        try {
            there = Json::parse(in);
        } catch (const nlohmann::json::exception& e) {
            throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
        }
        if (there != identity)
            throw std::runtime_error(dir.string() + ": holds another tune (another preset, objective, budget, views, "
                                     "seed or profile; see its tune.json); give another --out or remove it");
        return;
    }
    writeTextAtomic(file, identity.dump(2) + "\n");
}

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

EarlierRuns earlierRuns(const fs::path& dir) {
    EarlierRuns out;
    std::ifstream in(dir / "progress.json");
    if (!in) return out;
    try {
        const Json j = Json::parse(in);
        if (const auto it = j.find("secondsAllRuns"); it != j.end() && it->is_number() && it->get<double>() >= 0.0)
            out.seconds = it->get<double>();
        for (const auto& [key, scale] : {std::pair<const char*, int>{"screeningLimit", 1}, {"limit", kScreensPerEvaluation}})
            if (const auto it = j.find(key); it != j.end() && it->is_number_integer() && it->get<int>() > 0) {
                out.screeningLimit = it->get<int>() * scale;
                break;
            }
    } catch (const nlohmann::json::exception&) {
    }
    return out;
}

// The cheapest settings of the space on the input's scene: if they miss the budget, nothing fits.
Settings cheapest(Settings s) {
    s.cascades.count = 1;
    s.cascades.mapSize = 256;
    s.cascades.mapSizes.clear();
    s.cascades.manualSplits.clear();
    if (s.cascades.scheme == SplitScheme::Manual) s.cascades.scheme = SplitScheme::Practical;
    s.cascades.depthBounds = DepthBounds::Off;
    s.cascades.fit = FitMode::Cascade;
    s.cascades.blendBand = 0.0f;
    s.filter.kind = FilterKind::Hard;
    s.filter.screenSpace = ScreenSpace::Off;
    s.filter.contact = ContactShadows::Off;
    return s;
}

// Analytic biases, in texel units rather than metres, so they hold at any texel size: a slope
// of 1 texel per unit of tan with half a texel of normal offset; or seed 004's receiver-plane
// depth (the receiver's own slope across the texel) with a margin of half a texel of slope and
// nothing else (with none, the receiver's depth at the texel centre ties with the stored depth of
// the same surface and rounding decides: 30 % acne on truck-town). The descent did not reach the
// second by itself: on truck-town at ogldev-49's budget it tuned the bias in metres per cascade
// first, and from there the receiver plane alone scored worse (soft error 0.00913 against 0.00884).
Settings texelBias(Settings s) {
    s.bias.constant = 0.0f;
    s.bias.slope = 1.0f;
    s.bias.normalOffset = 0.5f;
    return s;
}
Settings planeBias(Settings s) {
    s.bias.constant = 0.0f;
    s.bias.slope = 0.5f;
    s.bias.normalOffset = 0.0f;
    s.bias.receiverPlane = true;
    return s;
}

// A method's maps placed on what the views show (SDSM, Lauritzen, Salvi and Lefohn 2011): light
// boxes fitted to the visible samples, each pixel reading the finest map that holds it, and the
// casters toward the light that a sample-tight box would cut drawn by a fixed reach (a tenth of
// the far plane), not the whole scene column; with the receiver-plane bias, which needs no trade
// between acne and light leaks. On truck-town this start is what takes ogldev-49's maps from
// 0.852 % to 0.464 % misclassified at less than its cost; the descent did not get there by single
// moves, as each alone either loses casters (the sample fit alone: 3.7 %) or costs more.
Settings seenBy(Settings s) {
    s.cascades.fit = FitMode::Samples;
    s.cascades.selection = Selection::Map;
    s.cascades.zExtension = ZExtension::Distance;
    s.cascades.zExtensionDistance = float(farPlaneShare(s, kZExtensionStartShare));
    return planeBias(s);
}

// The same with the splits' range cut to that tenth of the far plane where it reaches further:
// most of what a view shows is near (truck-town's preset camera: half its covered pixels within
// 22 m, 95 % within 98 m, 98 % within 304 m of its 1500 m far plane), so its maps' texels go
// there. On truck-town at ogldev-49's budget the tune from it ends at 0.403 % misclassified
// against 0.438 % without it (soft filtered 0.005284 against 0.005485).
Settings seenNear(Settings s) {
    s = seenBy(s);
    const float reach = float(farPlaneShare(s, kZExtensionStartShare));
    if (s.cascades.shadowDistance <= 0.0f || s.cascades.shadowDistance > reach) s.cascades.shadowDistance = reach;
    return s;
}

// Analytic starting points: splits from the depth range the camera actually sees (depth bounds:
// SDSM), a light box fitted to the visible samples, and each analytic bias.
std::vector<Settings> starts(const Settings& input) {
    Settings seen = input;
    seen.cascades.depthBounds = DepthBounds::Fit;
    seen.cascades.fit = FitMode::Samples;
    return {input, seen, texelBias(seen), planeBias(seen)};
}

// The first rung of the search's successive halving: half the output size, each side.
Settings screenSize(Settings s) {
    s.output.width = std::max(16, s.output.width / 2);
    s.output.height = std::max(16, s.output.height / 2);
    return s;
}

constexpr const char* kFlickerKey = "flicker.flipRate";

// Ctrl-C while waiting for another shard's measurement.
struct StoppedWhileWaiting {};

void widenLimits(Objective& o, const std::vector<std::pair<std::string, double>>& more) {
    for (const auto& [key, limit] : more)
        for (auto& [k, l] : o.atMost)
            if (k == key) l = std::max(l, limit);
}

class Tuner {
public:
    explicit Tuner(const TuneOptions& opt) : opt_(opt) {}

    TuneOutcome run() {
        const auto t0 = std::chrono::steady_clock::now();
        input_ = loadPreset(opt_.preset);
        if (opt_.size) std::tie(input_.output.width, input_.output.height) = *opt_.size;
        if (opt_.engine) {  // what the engine makes of the preset: the search starts there
            input_ = ontoEngine(*opt_.engine, input_);
            say("tuning for " + xport::engineName(*opt_.engine) + ": its knobs only (docs/engines.md)");
        }
        presetDir_ = fs::absolute(opt_.preset).parent_path();
        views_ = tuneViews(input_, opt_.views, opt_.holdOutEvery);
        references();
        claimFolder(opt_.outDir, identity());
        start_ = t0;
        const EarlierRuns earlier = earlierRuns(opt_.outDir);
        earlierSeconds_ = earlier.seconds;
        screeningLimit_ = earlier.screeningLimit > 0 ? earlier.screeningLimit : kScreensPerEvaluation * opt_.evaluations;
        journal_.emplace(opt_.outDir, opt_.shard);
        resumed_ = int(journal_->size());
        if (resumed_ > 0) say("resuming: " + std::to_string(resumed_) + " evaluations journaled in " + opt_.outDir.string());
        if (opt_.shard.sharded())
            say("shard " + std::to_string(opt_.shard.index) + "/" + std::to_string(opt_.shard.count) + ": measuring into " +
                journal_->file().string() + " and reading the other shards' journals there");
        try {
            return tune(t0);
        } catch (const StoppedWhileWaiting&) {
            TuneOutcome out;
            out.stopped = true;
            out.evaluations = made_;
            out.message = "stopped while waiting for another shard; run the same command to resume";
            return out;
        }
    }

private:
    TuneOutcome tune(std::chrono::steady_clock::time_point t0) {
        evaluator_.emplace(session_, presetDir_, views_, *opt_.profile, Objective{opt_.objective, {}});
        evaluator_->setPathFlicker(input_.path.frames > 0);
        evaluator_->setRendererPerView(opt_.rendererPerView);
        screener_.emplace(session_, presetDir_, std::vector<View>{views_.front()}, *opt_.profile, Objective{opt_.objective, {}});
        screener_->setRendererPerView(opt_.rendererPerView);
        resolveBudget();
        TuneOutcome out;
        const Evaluation cheap = measured(cheapest(input_), "tuned");
        if (!budget_.fits(judge(cheap, {opt_.objective, {}}))) {
            out.infeasible = true;
            out.message = "no settings fit the budget of " + budgetText(budget_) + ": the cheapest (1 cascade of 256^2, hard "
                          "filter) models " + fixed(judge(cheap, {}).costMs, 1) + " ms and " +
                          fixed(judge(cheap, {}).mapBytes / kMiB, 2) + " MiB on these views";
            return out;
        }
        const Evaluation inputRaw = measured(input_, "tuned");
        objective_ = {opt_.objective, artifactLimits(inputRaw.figures)};
        // With a path, the flicker F may not get worse than the references' (the input's when none
        // is given): a tune must not buy stills with shimmer.
        if (input_.path.frames > 0) objective_.atMost.push_back({kFlickerKey, flickerLimit(inputRaw)});
        // The references set the budget; their artifact shares are allowed too, or a reference
        // would not be a feasible answer at its own budget.
        for (const auto& [name, r] : refs_) widenLimits(objective_, artifactLimits(measured(r, "tuned").figures));
        if (!opt_.constraints) objective_.atMost.clear();
        SearchOptions so;
        so.budget = budget_;
        so.evaluations = opt_.evaluations;
        so.polish = opt_.evaluations / kPolishShare;
        so.front = opt_.front ? opt_.evaluations / kFrontShare : 0;
        so.frontFloorMs = judge(cheap, {}).costMs;
        so.screenings = screeningLimit_;
        so.seed = opt_.seed;
        so.stopRequested = [this] {
            return (opt_.stopRequested && opt_.stopRequested()) || (opt_.stopAfter >= 0 && made_ >= opt_.stopAfter);
        };
        so.progress = [this](const SearchProgress& p) { progress(p); };
        if (opt_.shard.sharded()) so.plan = [this](const Settings& from, const std::vector<Settings>& next) { plan(from, next); };
        so.screen = [this](const Settings& s) { return judge(measured(screenSize(s), "screen"), objective_); };
        const Space space = opt_.engine ? engineSpace(*opt_.engine, input_) : defaultSpace(input_);
        std::vector<Settings> from = starts(input_);
        // A reference's method is within budget by definition; so is it with an analytic bias.
        for (const auto& [name, r] : refs_) from.insert(from.end(), {r, texelBias(r), planeBias(r), seenBy(r), seenNear(r)});
        if (opt_.engine) {  // every start as the engine can take it; one it cannot (splits past its end) is dropped
            std::vector<Settings> onto;
            for (const Settings& s : from) {
                try {
                    onto.push_back(ontoEngine(*opt_.engine, s));
                } catch (const std::exception&) {
                }
            }
            from = std::move(onto);
        }
        const std::optional<Settings> earlier = earlierTuned();
        result_ = search(from, space, [this](const Settings& s) { return judge(measured(s, "tuned"), objective_); }, so);
        if (!result_.stopped && earlier) keepIfBetter(*earlier);
        out.evaluations = made_;
        out.resumed = resumed_;
        out.stopped = result_.stopped;
        if (out.stopped) {
            writeProgress("stopped", result_.evaluations, opt_.evaluations, &result_.evaluated);
            out.message = "stopped with " + std::to_string(journal_->size()) + " evaluations journaled in " +
                          (opt_.outDir / "evaluations.jsonl").string() + "; run the same command to resume";
            return out;
        }
        if (result_.best) simplify(*result_.best);
        if (opt_.front) sayFront();
        if (!result_.best) {
            writeProgress("infeasible", result_.evaluations, opt_.evaluations, &result_.evaluated);
            if (opt_.front && writes()) writeFront(nullptr);
            out.infeasible = true;
            out.message = "no point within the budget of " + budgetText(budget_) + " kept the artifact classes at the input's "
                          "level in " + std::to_string(result_.evaluations) + " evaluations";
            return out;
        }
        const Candidate& best = result_.evaluated[*result_.best];
        writeProgress("explaining", result_.evaluations, opt_.evaluations, &result_.evaluated);
        writeOutputs(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        writeProgress("done", result_.evaluations, opt_.evaluations, &result_.evaluated);
        out.evaluations = made_;
        out.fromShards = fromShards_;
        if (!writes()) {
            out.message = "shard " + std::to_string(opt_.shard.index) + "/" + std::to_string(opt_.shard.count) + " done: " +
                          std::to_string(made_) + " measured here, " + std::to_string(fromShards_) +
                          " by other shards; shard 1 writes the results to " + opt_.outDir.string();
            return out;
        }
        out.message = "tuned: " + errorText(opt_.objective, best.eval.error) + " " + sweep::errorFigure(opt_.objective).label +
                      " (input " + errorText(opt_.objective, judge(inputRaw, objective_).error) + ") at " +
                      fixed(best.eval.costMs, 1) + " ms modelled (budget " + budgetText(budget_) + ") -> " +
                      (opt_.outDir / "tuned.json").string();
        return out;
    }

    // The tuned preset a finished earlier run left in the folder (nothing for a new or an
    // interrupted one, so a resumed tune still ends where an uninterrupted one does). A run
    // continued with more evaluations walks elsewhere than the one it continues once the polish's
    // share moves (a tune of 40 polishes from its 30th evaluation, one of 160 from its 120th), and
    // did end worse: living-room as soft-shadows-blog 0.0024 -> 0.0181 soft filtered.
    std::optional<Settings> earlierTuned() const {
        const fs::path file = opt_.outDir / "tuned.json";
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) return std::nullopt;
        try {
            Settings s = loadPreset(file);
            s.scene = input_.scene;  // tuned.json's path is rebased for the folder
            return s;
        } catch (const SettingsError&) {
            return std::nullopt;  // a hand-edited file that no longer loads: the search's result stands
        }
    }

    // The earlier run's tuned preset becomes the result when it is better than the search's best
    // (its measurement is in the journal: free), so a continued tune never ends worse.
    void keepIfBetter(const Settings& earlier) {
        const Evaluation e = judge(measured(earlier, "tuned"), objective_);
        Candidate c{earlier, e, "the earlier run's tuned.json", e.valid && e.constraintsMet && budget_.fits(e),
                    budget_.excess(e)};
        if (!c.feasible || (result_.best && !better(c, result_.evaluated[*result_.best]))) return;
        // Silent when it is this run's own best, simplified last time (as cheap or cheaper, the same error).
        if (result_.best && e.error < result_.evaluated[*result_.best].eval.error)
            say("kept the earlier run's tuned preset (" + errorText(opt_.objective, e.error) + " at " + fixed(e.costMs, 1) +
                " ms): better than this run's best (" + errorText(opt_.objective, result_.evaluated[*result_.best].eval.error) + ")");
        result_.evaluated.push_back(std::move(c));
        result_.best = result_.evaluated.size() - 1;
        keptEarlier_ = true;
    }

    void say(const std::string& line) const {
        if (opt_.progress) opt_.progress(line);
    }

    // The journaled measurement of `s` on `views`, or a new one (journaled at once).
    // A sharded tune waits for the shard that owns `s` unless `waitForOwner` is false.
    Evaluation measured(const Settings& s, const std::string& views, bool waitForOwner = true) {
        if (std::optional<Evaluation> e = journal_->find(s, views)) return *e;
        if (opt_.shard.sharded()) {
            if (std::optional<Evaluation> e = fromAnotherShard(s, views, waitForOwner)) return *e;
        }
        const auto t0 = std::chrono::steady_clock::now();
        Evaluation e = views == "screen" ? screener_->measure(s, false) : evaluator_->measure(s, views == "held-out");
        (views == "screen" ? screenMs_ : evalMs_)
            .push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        journal_->add(s, views, e);
        ++made_;
        return e;
    }

    bool writes() const { return opt_.shard.index == 1; }

    // The measurement of a point another shard owns, once it is in that shard's journal; nothing
    // when this shard owns it, or when the others fell silent (then this shard measures it).
    std::optional<Evaluation> fromAnotherShard(const Settings& s, const std::string& views, bool wait) {
        journal_->refresh();
        if (std::optional<Evaluation> e = journal_->find(s, views)) return ++fromShards_, e;
        const int owner = ownerOf(s, views, opt_.shard.count);
        if (!wait || owner == opt_.shard.index || othersSilent_) return std::nullopt;
        const auto t0 = std::chrono::steady_clock::now();
        const auto deadline = t0 + std::chrono::duration<double>(opt_.shardWaitSeconds);
        while (std::chrono::steady_clock::now() < deadline) {
            if (opt_.stopRequested && opt_.stopRequested()) throw StoppedWhileWaiting{};
            if (!measureAhead(s)) std::this_thread::sleep_for(std::chrono::milliseconds(50));
            journal_->refresh();
            if (std::optional<Evaluation> e = journal_->find(s, views)) return ++fromShards_, e;
        }
        othersSilent_ = true;
        say("warning: shard " + std::to_string(owner) + "/" + std::to_string(opt_.shard.count) + " wrote nothing in " +
            fixed(opt_.shardWaitSeconds, 0) + " s; this shard measures every point from now on");
        return std::nullopt;
    }

    // A sharded round's plan: the neighbours the search will try from `from`, in its order. While
    // this shard waits for another's measurement, it measures what it owns of the next few
    // neighbours, as the search would (screened first when `from` is within the budget); every
    // search then finds them in the journals. The window bounds the work spent on a round the
    // search leaves early (its first better neighbour ends it).
    void plan(const Settings& from, std::vector<Settings> next) {
        planFrom_ = from;
        plan_ = std::move(next);
    }

    bool owned(const Settings& s, const std::string& views) const {
        return ownerOf(s, views, opt_.shard.count) == opt_.shard.index && !journal_->find(s, views);
    }

    // One measurement ahead of `waitedFor` in the plan: true when it made one.
    bool measureAhead(const Settings& waitedFor) {
        std::size_t i = 0;
        while (i < plan_.size() && !(plan_[i] == waitedFor) && !(screenSize(plan_[i]) == waitedFor)) ++i;
        const std::optional<Evaluation> from = journal_->find(planFrom_, "tuned");
        if (i == plan_.size() || !from) return false;
        const Evaluation at = judge(*from, objective_);
        const bool screen = at.valid && at.constraintsMet && budget_.fits(at);
        const std::optional<Evaluation> fromScreen = journal_->find(screenSize(planFrom_), "screen");
        const std::size_t end = std::min(plan_.size(), i + 1 + 2 * std::size_t(opt_.shard.count));
        for (std::size_t k = i + 1; k < end; ++k) {
            const Settings& s = plan_[k];
            if (screen && owned(screenSize(s), "screen")) return measured(screenSize(s), "screen", false), true;
            if (!owned(s, "tuned")) continue;
            if (screen) {
                const std::optional<Evaluation> mine = journal_->find(screenSize(s), "screen");
                if (!mine || !fromScreen) continue;
                const Evaluation a = judge(*mine, objective_), b = judge(*fromScreen, objective_);
                if (!a.valid || !b.valid || !worthFullEvaluation(a, b, at, budget_)) continue;
            }
            measured(s, "tuned", false);
            return true;
        }
        return false;
    }

    // The flicker limit: the largest F of the references, or the input's own with none.
    double flickerLimit(const Evaluation& input) {
        auto f = [](const Evaluation& e) {
            const auto it = e.figures.find(kFlickerKey);
            return it != e.figures.end() && it->is_number() ? it->get<double>() : 0.0;
        };
        if (refs_.empty()) return f(input);
        double limit = 0.0;
        for (const auto& [name, r] : refs_) limit = std::max(limit, f(measured(r, "tuned")));
        return limit;
    }

    void references() {
        for (const fs::path& file : opt_.budgetFrom) {
            std::vector<std::string> adapted;
            const Settings ref = loadPreset(file);
            refs_.push_back({file.stem().string(), sweep::referenceOnBase(input_, ref, file.stem().string(), adapted)});
            for (const std::string& a : adapted) say("note: reference " + a);
        }
        // For an engine with no budget given: its defaults on this scene and views set the budget
        // and are the baseline the tune must beat.
        if (opt_.engine && !opt_.budgetMs && !opt_.budgetMiB && opt_.budgetFrom.empty())
            refs_.push_back({xport::engineName(*opt_.engine) + "-defaults",
                             xport::engineModel(*opt_.engine, xport::defaultKnobs(*opt_.engine), input_)});
        for (const fs::path& file : opt_.compareWith) {
            std::vector<std::string> adapted;
            compared_.push_back({file.stem().string(), sweep::referenceOnBase(input_, loadPreset(file), file.stem().string(), adapted)});
        }
    }

    Json identity() const {
        Json refs = Json::array();
        for (const auto& [name, s] : refs_) refs.push_back({{"name", name}, {"settings", toOrderedJson(s)}});
        Json j = {{"version", kTuneVersion},
                {"input", toOrderedJson(input_)},
                {"objective", opt_.objective},
                {"budgetMs", opt_.budgetMs ? Json(*opt_.budgetMs) : Json(nullptr)},
                {"budgetMiB", opt_.budgetMiB ? Json(*opt_.budgetMiB) : Json(nullptr)},
                {"budgetFrom", refs},
                {"views", opt_.views},
                {"holdOutEvery", opt_.holdOutEvery},
                {"seed", opt_.seed},
                {"costProfile", metrics::profileName(*opt_.profile)}};
        if (opt_.engine) j["engine"] = xport::engineName(*opt_.engine);
        // Only when not the default, so folders of earlier tunes still resume.
        if (!opt_.constraints) j["constraints"] = "none";
        if (opt_.front) j["front"] = true;
        return j;
    }

    // --budget-ms / --budget-mib as given; --budget-from: the cheapest reference's modelled cost
    // and memory on the input's scene and tuned views.
    void resolveBudget() {
        if (opt_.budgetMs) budget_.ms = *opt_.budgetMs;
        if (opt_.budgetMiB) budget_.bytes = *opt_.budgetMiB * kMiB;
        for (const auto& [name, s] : refs_) {
            const Evaluation e = judge(measured(s, "tuned"), {opt_.objective, {}});
            if (!e.valid) throw std::runtime_error("reference " + name + ": " + e.problem);
            say("reference " + name + ": " + fixed(e.costMs, 1) + " ms modelled, " + fixed(e.mapBytes / kMiB, 1) + " MiB, " +
                errorText(opt_.objective, e.error) + " " + sweep::errorFigure(opt_.objective).label);
            if (!opt_.budgetMs) budget_.ms = std::min(budget_.ms.value_or(e.costMs), e.costMs);
            if (!opt_.budgetMiB) budget_.bytes = std::min(budget_.bytes.value_or(e.mapBytes), e.mapBytes);
        }
        if (!budget_.ms && !budget_.bytes) throw std::runtime_error("give a budget: --budget-ms, --budget-mib or --budget-from");
        say("budget: " + budgetText(budget_) + " (modelled with " + metrics::profileName(*opt_.profile) + ")");
    }

    void progress(const SearchProgress& p) {
        std::string line = "tune [" + std::to_string(p.evaluations + 1) + "/" + std::to_string(p.limit) + "] ";
        if (p.screenings) line += "(" + std::to_string(p.screenings) + " screened) ";
        if (p.best) {
            const Candidate& b = (*p.evaluated)[*p.best];
            line += "best " + errorText(opt_.objective, b.eval.error) + " at " + fixed(b.eval.costMs, 1) + " ms";
        } else {
            line += "nothing within the budget yet";
        }
        say(line + "; trying " + p.trying);
        writeProgress("searching", p.evaluations, p.limit, p.evaluated);
    }

    Json pointJson(const Evaluation& e) const {
        return {{"error", e.error}, {"costMs", e.costMs}, {"mapBytes", e.mapBytes}};
    }

    // progress.json: what a UI draws while the tune runs (docs/tuning.md#progress). Evaluations
    // within the budget and the constraints are "feasible"; the input and the references are
    // measured before the search starts, so they are there from the first write.
    void writeProgress(const std::string& stage, int done, int limit, const std::vector<Candidate>* evaluated) {
        if (!writes()) return;
        Json refs = Json::object();
        for (const auto* list : {&refs_, &compared_})
            for (const auto& [name, r] : *list) {
                Json j = pointJson(judge(measured(r, "tuned", list == &refs_), objective_));
                j["budget"] = list == &refs_;
                refs[name] = std::move(j);
            }
        Json points = Json::array();
        std::optional<std::size_t> best;
        if (evaluated)
            for (std::size_t i = 0; i < evaluated->size(); ++i) {
                const Candidate& c = (*evaluated)[i];
                if (!c.eval.valid) continue;
                Json j = pointJson(c.eval);
                j["feasible"] = c.feasible;
                j["onFront"] = onFront(c);
                points.push_back(std::move(j));
                if (c.feasible && (!best || better(c, (*evaluated)[*best]))) best = i;
            }
        const Json progress = {{"version", kTuneVersion},
                               {"stage", stage},
                               {"evaluations", done},
                               {"limit", limit},
                               {"screeningLimit", screeningLimit_},
                               {"objective", opt_.objective},
                               {"budgetMs", budget_.ms ? Json(*budget_.ms) : Json(nullptr)},
                               {"budgetBytes", budget_.bytes ? Json(*budget_.bytes) : Json(nullptr)},
                               {"input", pointJson(judge(measured(input_, "tuned"), objective_))},
                               {"references", refs},
                               {"best", best ? pointJson((*evaluated)[*best].eval) : Json(nullptr)},
                               {"secondsAllRuns", secondsAllRuns()},
                               {"points", points}};
        writeTextAtomic(opt_.outDir / "progress.json", progress.dump() + "\n");
    }

    Json evalJson(const Evaluation& e) const {
        return {{"error", e.error}, {"costMs", e.costMs}, {"mapBytes", e.mapBytes}, {"constraintsMet", e.constraintsMet},
                {"violated", e.violated}, {"figures", e.figures}};
    }

    // The tuned preset without the changes that buy nothing: a change whose removal keeps the point
    // within the budget and the constraints at no more error and no more cost is undone (a
    // restart's random moves ride along otherwise). These are the evaluations the explanation's
    // "in the tuned preset" needs anyway.
    void simplify(std::size_t best) {
        Candidate c = result_.evaluated[best];
        // Points already stood on: two linked fields (manual splits and their scheme) can undo each
        // other in turn for ever when neither buys anything (seen with tune --engine threejs).
        std::vector<Settings> visited{c.settings};
        for (bool undone = true; undone;) {
            undone = false;
            for (const Change& ch : changesBetween(input_, c.settings)) {
                Settings without;
                try {
                    without = withFieldJson(c.settings, ch.path, ch.from);
                } catch (const SettingsError&) {
                    continue;
                }
                if (opt_.engine) {  // a field put back must still be something the engine can set
                    try {
                        without = ontoEngine(*opt_.engine, without);
                    } catch (const std::exception&) {
                        continue;
                    }
                }
                if (without == c.settings || !validate(without).empty()) continue;
                if (std::find(visited.begin(), visited.end(), without) != visited.end()) continue;
                visited.push_back(without);
                const Evaluation e = judge(measured(without, "tuned"), objective_);
                if (e.valid && e.constraintsMet && budget_.fits(e) && e.error <= c.eval.error && e.costMs <= c.eval.costMs) {
                    say("simplified: " + ch.path + " back to " + (ch.from.is_string() ? ch.from.get<std::string>() : ch.from.dump()) +
                        " (it bought nothing)");
                    c = {without, e, c.move + ", simplified", true, 0.0};
                    undone = true;
                    break;
                }
            }
        }
        result_.evaluated.push_back(std::move(c));
        result_.best = result_.evaluated.size() - 1;
    }

    // <engine>.json: the knobs (engine-check --knobs takes its "knobs"); the paste-ready text beside.
    void writeEngineOutputs(xport::Engine e, const Settings& best) const {
        const xport::EngineKnobs k = xport::knobsFor(e, best);
        const std::string name = xport::engineName(e);
        writeTextAtomic(opt_.outDir / (name + ".json"), Json{{"engine", name}, {"knobs", k.knobs}, {"lacks", k.lacks}}.dump(2) + "\n");
        for (const xport::PasteText& t : xport::engineSnippets(e, k.knobs)) {
            writeTextAtomic(opt_.outDir / t.file, t.text);
            say("wrote " + (opt_.outDir / t.file).string());
        }
        if (!k.lacks.empty()) say("  " + name + " lacks: " + k.lacks.front());
    }

    void writeOutputs(const Candidate& best, double seconds) {
        const fs::path& dir = opt_.outDir;
        if (writes()) {
            const Json tuned = sweep::presetInFolder(dir, presetDir_, toOrderedJson(best.settings));
            writeTextAtomic(dir / "tuned.json", tuned.dump(2) + "\n");
            loadPreset(dir / "tuned.json");  // never leave a preset that does not load again
            if (opt_.engine) writeEngineOutputs(*opt_.engine, best.settings);
            writeFront(&best);
        }
        // Every shard makes the measurements below, in the same order, so they share them.
        const Evaluator judged = [this](const Settings& s) { return judge(measured(s, "tuned"), objective_); };
        const Evaluation inputEval = judged(input_);
        const Explanation why = explain(input_, inputEval, best.settings, best.eval, opt_.objective, judged);
        if (writes()) {
            writeTextAtomic(dir / "explain.json", toJson(why).dump(2) + "\n");
            writeTextAtomic(dir / "explain.md", toMarkdown(why, "Why " + opt_.preset.stem().string() + " was tuned this way"));
            for (const Explained& x : why.changes) say("  " + x.line);
        }
        writeSummary(best, inputEval, seconds);
    }

    // Every evaluated point (and the input and references) as a sweep's results: the Pareto charts
    // of modelled cost and memory against the objective, and the front's presets.
    // A point front/ charts: within the budget and the constraints; with --front, within the
    // budget (the descent's rungs are judged on the objective alone).
    bool onFront(const Candidate& c) const { return c.feasible || (opt_.front && c.eval.valid && budget_.fits(c.eval)); }

    // The points of front/ that no other is better than in both cost and error, cheapest first.
    std::vector<const Candidate*> frontPoints() const {
        std::vector<const Candidate*> out;
        for (std::size_t i : costErrorFront(result_.evaluated, [this](const Candidate& c) { return onFront(c); }))
            out.push_back(&result_.evaluated[i]);
        return out;
    }

    Json frontJson() const {
        Json front = Json::array();
        for (const Candidate* c : frontPoints())
            front.push_back({{"costMs", c->eval.costMs}, {"mapBytes", c->eval.mapBytes}, {"error", c->eval.error},
                             {"constraintsMet", c->eval.constraintsMet}, {"violated", c->eval.violated},
                             {"id", settingsId(c->settings)}, {"move", c->move}});
        return front;
    }

    void sayFront() const {
        const std::vector<const Candidate*> f = frontPoints();
        if (f.empty()) return say("front: no point within the budget");
        say("front: " + std::to_string(f.size()) + " points within the budget, from " + fixed(f.front()->eval.costMs, 1) + " ms (" +
            errorText(opt_.objective, f.front()->eval.error) + ") to " + fixed(f.back()->eval.costMs, 1) + " ms (" +
            errorText(opt_.objective, f.back()->eval.error) + "); " + std::to_string(result_.frontRungs) +
            " evaluations on the descent -> " + (opt_.outDir / "front" / "front.json").string());
    }

    void writeFront(const Candidate* best) {
        sweep::Manifest m;
        m.sweep = opt_.preset.stem().string();  // the chart's title starts with it: keep it short
        m.scene = input_.scene;
        m.presetDir = presetDir_;
        m.width = input_.output.width;
        m.height = input_.output.height;
        m.machine = opt_.machine;
        m.costProfile = metrics::profileName(*opt_.profile);
        std::vector<sweep::PointResult> points;
        auto add = [&](const Settings& s, const Evaluation& e, std::string label, bool reference) {
            if (!e.valid) return;
            sweep::PointResult r{settingsId(s), std::move(label), reference, {}, toOrderedJson(s), {}};
            for (const auto& [key, value] : e.figures.items()) r.figures.push_back({key, value.is_number() ? value.get<double>() : NAN});
            m.pointIds.push_back(r.id);
            points.push_back(std::move(r));
        };
        add(input_, measured(input_, "tuned"), "input", true);
        for (const auto& [name, s] : refs_) add(s, measured(s, "tuned"), name, true);
        for (const auto& [name, s] : compared_) add(s, measured(s, "tuned", false), name, true);
        // Labels stay short for the chart's front table: the moves that led to a point are in
        // evaluations.jsonl and explain.md.
        for (std::size_t i = 0; i < result_.evaluated.size(); ++i) {
            const Candidate& c = result_.evaluated[i];
            if (onFront(c) && !(c.settings == input_))
                add(c.settings, c.eval, &c == best ? "tuned" : "evaluation " + std::to_string(i + 1), false);
        }
        sweep::writeReport(opt_.outDir / "front", m, points, {opt_.objective, "model"});
    }

    void writeSummary(const Candidate& best, const Evaluation& inputEval, double seconds) {
        Json views = Json::array();
        bool heldOut = false;
        for (const View& v : views_) {
            views.push_back({{"name", v.name}, {"heldOut", v.heldOut}});
            heldOut = heldOut || v.heldOut;
        }
        Json s = {{"preset", opt_.preset.string()},
                  {"objective", opt_.objective},
                  {"budgetMs", budget_.ms ? Json(*budget_.ms) : Json(nullptr)},
                  {"budgetBytes", budget_.bytes ? Json(*budget_.bytes) : Json(nullptr)},
                  {"views", views},
                  {"evaluations", result_.evaluations},
                  {"search", {{"evaluations", result_.evaluations}, {"evaluationsToBest", result_.evaluationsToBest},
                              {"screenings", result_.screenings}, {"screenedOut", result_.screenedOut},
                              {"polished", result_.polished}, {"frontRungs", result_.frontRungs},
                              {"keptEarlier", keptEarlier_}}},
                  {"seed", opt_.seed},
                  {"seconds", seconds},
                  {"secondsAllRuns", earlierSeconds_ + seconds},
                  {"input", {{"tuned", evalJson(inputEval)}}},
                  {"tuned", {{"tuned", evalJson(best.eval)}}},
                  {"references", Json::object()}};
        if (opt_.front) s["front"] = frontJson();
        for (const auto& [name, r] : refs_) s["references"][name] = {{"tuned", evalJson(judge(measured(r, "tuned"), objective_))}};
        if (!compared_.empty()) s["compared"] = Json::object();
        for (const auto& [name, r] : compared_) s["compared"][name] = {{"tuned", evalJson(judge(measured(r, "tuned", false), objective_))}};
        if (heldOut) {
            const Evaluation in = judge(measured(input_, "held-out"), objective_);
            const Evaluation tu = judge(measured(best.settings, "held-out"), objective_);
            s["input"]["heldOut"] = evalJson(in);
            s["tuned"]["heldOut"] = evalJson(tu);
            std::vector<HeldOutScore> refScores;
            for (const auto& [name, r] : refs_) {
                const Evaluation held = judge(measured(r, "held-out"), objective_);
                s["references"][name]["heldOut"] = evalJson(held);
                refScores.push_back({name, judge(measured(r, "tuned"), objective_).error, held.error});
            }
            const HeldOutVerdict v = heldOutVerdict({"input", inputEval.error, in.error}, refScores,
                                                    {"tuned", best.eval.error, tu.error});
            s["heldOutHolds"] = v.holds;
            s["heldOutJudged"] = v.judged;
            s["heldOutBaseline"] = v.baseline;
            const Json& baseHeld = v.baseline == "input" ? s["input"]["heldOut"] : s["references"][v.baseline]["heldOut"];
            const std::string verdict = !v.judged ? "held-out views (nothing to judge: no error there for either): "
                                        : v.holds ? "held-out views: "
                                                  : "warning: the tune does not hold on the held-out views: ";
            say(verdict +
                errorText(opt_.objective, baseHeld["error"].get<double>()) + " " + v.baseline + " -> " +
                errorText(opt_.objective, tu.error) + " tuned (on the tuned views " +
                errorText(opt_.objective, best.eval.error + v.gainTuned) + " -> " + errorText(opt_.objective, best.eval.error) + ")");
        }
        const metrics::MeasureTimings& t = evaluator_->spent();
        const double n = std::max(1, evaluator_->measurements());
        // A median of nothing is no figure (a resumed tune that found every point in its journal).
        const auto medianOf = [](const std::vector<double>& ms) { return ms.empty() ? Json(nullptr) : Json(metrics::median(ms)); };
        s["timing"] = {{"evaluationsMeasured", evalMs_.size()},
                       {"medianMsPerEvaluation", medianOf(evalMs_)},
                       {"screeningsMeasured", screenMs_.size()},
                       {"medianMsPerScreening", medianOf(screenMs_)},
                       {"meanMsPerViewMeasurement", t.totalMs / n},
                       {"meanRenderAndReadBackMs", t.measurePassMs / n},
                       {"meanTruthMs", t.groundTruthMs / n},
                       {"meanSoftTruthMs", t.softTruthMs / n},
                       {"mapsDrawn", evaluator_->mapsDrawn() + screener_->mapsDrawn()},
                       {"mapsKept", evaluator_->mapsKept() + screener_->mapsKept()}};
        if (evalMs_.empty() && screenMs_.empty()) {
            say("time: nothing measured in this run (every point was in the journal)");
        } else {
            say("time: median " + fixed(metrics::median(evalMs_), 0) + " ms per evaluation (" + std::to_string(evalMs_.size()) +
            " measured), " + fixed(metrics::median(screenMs_), 0) + " ms per screening (" + std::to_string(screenMs_.size()) +
            "; one view at half size); per view " + fixed(t.totalMs / n, 0) + " ms (render and read-back " + fixed(t.measurePassMs / n, 0) +
            ", truth " + fixed(t.groundTruthMs / n, 0) + ", soft truth " + fixed(t.softTruthMs / n, 0) + ")");
        }
        if (writes()) writeTextAtomic(opt_.outDir / "summary.json", s.dump(2) + "\n");
    }

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
    double secondsAllRuns() const {
        return earlierSeconds_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    bool othersSilent_ = false;  // a shard wrote nothing in opt_.shardWaitSeconds
    Settings planFrom_;           // the search's current round (plan())
    std::vector<Settings> plan_;
    std::vector<double> evalMs_;    // wall-clock of each new evaluation on the tuned or held-out views
    std::vector<double> screenMs_;  // ... of each new screening (the preset camera at half size)
};

}  // namespace

TuneOutcome runTune(const TuneOptions& opt) {
    if (!opt.profile) throw std::invalid_argument("tune: no cost profile");
    return Tuner(opt).run();
}

}  // namespace st::tune
