#pragma once
// Scores settings for the tuner: measures them on each view (metrics::MeasureSession, which keeps
// the scene, renderer, BVH and each view's traced truth), with the cost counted and modelled
// rather than timed, and reduces the views to one Evaluation. Needs a current GL 4.5 context.
#include "metrics/cost_model.h"
#include "metrics/measure_session.h"
#include "tune/tune_search.h"
#include "tune/tune_views.h"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace st::tune {

// What the tune minimises, and what may not get worse.
struct Objective {
    std::string error = "soft-filtered";  // a figure table --error choice (sweep::errorKey)
    // figure key -> the most it may be (raw units): the artifact classes, flicker.
    std::vector<std::pair<std::string, double>> atMost;
};

// The default constraints: each artifact class of the soft truth (acne, light bleeding,
// peter-panning, missing caster) no worse than `start`'s share plus `slack` (a share: 0.0005 is
// 0.05 percentage points), so the error falls without trading one artifact for another.
std::vector<std::pair<std::string, double>> artifactLimits(const nlohmann::ordered_json& startFigures,
                                                           double slack = 0.0005);

// `e` (its figures) judged by `o`: the error, the modelled cost, the constraints; invalid when
// the objective's figure or the cost was not measured.
Evaluation judge(Evaluation e, const Objective& o);

class ViewEvaluator {
public:
    ViewEvaluator(metrics::MeasureSession& session, std::filesystem::path presetDir, std::vector<View> views,
                  const metrics::CostProfile& profile, Objective objective);
    void setObjective(Objective o) { objective_ = std::move(o); }
    // With a camera path: the preset camera's view also measures the flicker F along the path
    // (flicker.flipRate), which the tune holds as a constraint (docs/tuning.md#views).
    void setPathFlicker(bool on) { pathFlicker_ = on; }
    // One renderer per view (the default): each view keeps its maps while candidates differ only
    // in what the maps do not hold (filter, bias); off, the session's one renderer draws every
    // view and redraws every map at each change of view (the baseline of scripts/bench_tune.sh).
    void setRendererPerView(bool on) { perView_ = on; }
    const Objective& objective() const { return objective_; }

    // On the tuned views (those not held out): figures averaged over the views (map bytes: the
    // largest), judged by the objective.
    Evaluation operator()(const Settings& s) { return judge(measure(s, false), objective_); }
    // The figures alone (not judged), on the tuned or the held-out views (none held out: the tuned ones).
    Evaluation measure(const Settings& s, bool heldOut);
    int measurements() const { return measurements_; }
    // Cascade maps drawn and kept over every measurement so far (FrameStats::cascades[i].redrawn).
    int mapsDrawn() const { return mapsDrawn_; }
    int mapsKept() const { return mapsKept_; }
    // Wall-clock milliseconds spent per view measurement, summed by stage (MeasureTimings).
    const metrics::MeasureTimings& spent() const { return spent_; }

private:
    metrics::MeasureSession& session_;
    std::filesystem::path presetDir_;
    std::vector<View> views_;
    const metrics::CostProfile& profile_;
    Objective objective_;
    int measurements_ = 0;
    bool pathFlicker_ = false;
    bool perView_ = true;
    int mapsDrawn_ = 0, mapsKept_ = 0;
    std::vector<std::shared_ptr<Renderer>> renderers_;  // per view, for the scene below (a copy shares them)
    const Scene* rendererScene_ = nullptr;
    Renderer* rendererFor(std::size_t view, const Settings& sv);
    metrics::MeasureTimings spent_;
};

// An evaluation's measured part (validity and figures) <-> JSON, exactly: the tune's journal, read
// back by a resumed tune and judged again (judge()).
nlohmann::ordered_json toJson(const Evaluation& e);
Evaluation evaluationFromJson(const nlohmann::ordered_json& j);

}  // namespace st::tune
