// summary.json: the tuned, input and reference figures on the tuned and held-out views, and the time.
#include "tune/tuner.h"

#include "metrics/cost.h"
#include "metrics/figure_table.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"
#include "tune/tune_engine.h"
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

namespace st::tune::detail {

void Tuner::writeSummary(const Candidate& best, const Evaluation& inputEval, double seconds) {
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

}  // namespace st::tune::detail
