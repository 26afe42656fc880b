#include "tune/tune_eval.h"

#include "metrics/figure_table.h"
#include "sweep/sweep_results.h"

#include <cmath>
#include <map>

namespace st::tune {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {
constexpr const char* kArtifactKeys[] = {"soft.acne", "soft.lightBleeding", "soft.peterPanning", "soft.missingCaster"};
constexpr const char* kMapBytesKey = "cost.mapBytes";

double figure(const Json& figures, const std::string& key) {
    const auto it = figures.find(key);
    return it == figures.end() || !it->is_number() ? NAN : it->get<double>();
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f %%", share * 100.0);
    return text;
}
}  // namespace

std::vector<std::pair<std::string, double>> artifactLimits(const Json& startFigures, double slack) {
    std::vector<std::pair<std::string, double>> out;
    for (const char* key : kArtifactKeys) {
        const double start = figure(startFigures, key);
        if (std::isfinite(start)) out.push_back({key, start + slack});
    }
    return out;
}

ViewEvaluator::ViewEvaluator(metrics::MeasureSession& session, fs::path presetDir, std::vector<View> views,
                             const metrics::CostProfile& profile, Objective objective)
    : session_(session), presetDir_(std::move(presetDir)), views_(std::move(views)), profile_(profile),
      objective_(std::move(objective)) {}

Renderer* ViewEvaluator::rendererFor(std::size_t view, const Settings& sv) {
    if (!perView_) return nullptr;
    const Scene* scene = session_.entryFor(sv, presetDir_).scene.get();
    if (scene != rendererScene_) renderers_.clear(), rendererScene_ = scene;
    if (renderers_.size() < views_.size()) renderers_.resize(views_.size());
    if (!renderers_[view]) renderers_[view] = std::make_shared<Renderer>(*scene);
    return renderers_[view].get();
}

Evaluation ViewEvaluator::measure(const Settings& s, bool heldOut) {
    bool any = false;
    for (const View& v : views_) any = any || v.heldOut == heldOut;
    metrics::MeasureOptions mo;
    mo.costFrames = 0;  // counted and modelled, not timed: the same in every run
    mo.costProfile = &profile_;
    mo.flicker = false;
    mo.shadeMain = false;  // the figures come from the measurement pass; the counted work is the same
    std::map<std::string, std::pair<double, int>> sums;  // key -> (sum, views with a value)
    std::vector<std::string> order;
    double mapBytes = 0.0;
    for (const View& v : views_) {
        if (any && v.heldOut != heldOut) continue;
        metrics::PresetMeasurement m;
        // The flicker along the preset's own path, measured once: with the preset camera.
        const bool flicker = pathFlicker_ && !heldOut && &v == &views_.front() && s.path.frames > 0;
        Settings sv = onView(s, v);
        if (flicker) sv.path = s.path;
        mo.flicker = flicker;
        try {
            mo.renderer = rendererFor(std::size_t(&v - views_.data()), sv);
            m = session_.measure(sv, presetDir_, mo);
        } catch (const std::invalid_argument& err) {  // settings the cascade math rejects on this view
            Evaluation bad;
            bad.valid = false;
            bad.problem = v.name + ": " + err.what();
            bad.figures = Json::object();
            return bad;
        }
        ++measurements_;
        for (const CascadeStats& c : m.frame.cascades) ++(c.redrawn ? mapsDrawn_ : mapsKept_);
        spent_.measurePassMs += m.timings.measurePassMs;
        spent_.groundTruthMs += m.timings.groundTruthMs;
        spent_.softTruthMs += m.timings.softTruthMs;
        spent_.totalMs += m.timings.totalMs;
        for (const auto& [key, value] : sweep::figuresOf(m)) {
            auto [it, added] = sums.try_emplace(key, 0.0, 0);
            if (added) order.push_back(key);
            if (std::isfinite(value)) it->second.first += value, ++it->second.second;
            if (key == kMapBytesKey && std::isfinite(value)) mapBytes = std::max(mapBytes, value);
        }
    }
    Evaluation e;
    e.figures = Json::object();
    for (const std::string& key : order) {
        const auto& [sum, n] = sums[key];
        e.figures[key] = n > 0 ? Json(sum / n) : Json(nullptr);
    }
    e.figures[kMapBytesKey] = mapBytes;
    return e;
}

Evaluation judge(Evaluation e, const Objective& o) {
    e.mapBytes = figure(e.figures, kMapBytesKey);
    e.error = figure(e.figures, sweep::errorKey(o.error));
    e.costMs = figure(e.figures, "cost.modelMs");
    e.constraintsMet = true;
    e.violated.clear();
    if (e.valid && (!std::isfinite(e.error) || !std::isfinite(e.costMs))) {
        e.valid = false;  // e.g. flicker as the objective of a preset without a path
        e.problem = "the objective (" + o.error + ") or the modelled cost was not measured for these settings";
    }
    for (const auto& [key, limit] : o.atMost) {
        const double value = figure(e.figures, key);
        if (std::isfinite(value) && value > limit) {
            e.constraintsMet = false;
            const metrics::FigureRow* row = metrics::findFigure(key);
            e.violated += (e.violated.empty() ? "" : "; ") + std::string(row ? row->label : key) + " " + percent(value) +
                          " > " + percent(limit);
        }
    }
    return e;
}

Json toJson(const Evaluation& e) {
    return {{"valid", e.valid}, {"problem", e.problem}, {"figures", e.figures}};
}

Evaluation evaluationFromJson(const Json& j) {
    Evaluation e;
    e.valid = j.at("valid").get<bool>();
    e.problem = j.at("problem").get<std::string>();
    e.figures = j.at("figures");
    return e;
}

}  // namespace st::tune
