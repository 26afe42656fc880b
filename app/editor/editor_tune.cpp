#include "app/editor/editor_tune.h"

#include "metrics/figure_table.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "report/pareto.h"
#include "sweep/sweep_results.h"

#include <sys/wait.h>  // WIFEXITED

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace st::app {
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr double kMiB = 1024.0 * 1024.0;

std::string fixed(double v, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

// A raw objective value in the figure table's display unit, to 4 significant digits (errors span
// 1e-5 .. 1): "0.5184 %", "0.000512".
std::string errorText(const metrics::FigureRow& row, double raw) {
    if (!std::isfinite(raw)) return "-";
    const metrics::UnitInfo& u = metrics::unitInfo(row.unit);
    char text[48];
    std::snprintf(text, sizeof text, "%.4g", raw * u.scale);
    return text + (u.symbol[0] ? " " + std::string(u.symbol) : "");
}

double number(const Json& j, const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_number() ? it->get<double>() : NAN;
}

ui::SweepPoint chartPoint(const Json& j, std::string label, bool reference, const metrics::FigureRow& error) {
    ui::SweepPoint p;
    p.label = std::move(label);
    p.reference = reference;
    p.cost = number(j, "costMs");
    p.memory = number(j, "mapBytes") / kMiB;
    p.error = metrics::shown(error.unit, number(j, "error"));
    p.figures = error.label + " " + errorText(error, number(j, "error")) + "\nmodelled cost " + fixed(p.cost, 1) +
                " ms\nmap memory " + fixed(p.memory, 1) + " MiB";
    return p;
}

std::optional<Json> readJson(const fs::path& file) {
    std::ifstream in(file);
    if (!in) return std::nullopt;
    try {
        return Json::parse(in);
    } catch (const Json::exception&) {
        return std::nullopt;  // not there yet in full: progress.json is renamed into place, so this is rare
    }
}

}  // namespace

std::vector<std::string> tuneArguments(const ui::TuneRequest& r, const fs::path& dir, bool withA) {
    std::vector<std::string> args = {"tune", (dir / "base.json").string(), "--out", (dir / "out").string(),
                                     "--objective", r.objective, "--evaluations", std::to_string(r.evaluations),
                                     "--views", std::to_string(r.views),
                                     "--size", std::to_string(r.width) + "x" + std::to_string(r.height)};
    // One held-out view when there are at least two: the last.
    args.insert(args.end(), {"--hold-out-every", std::to_string(r.views > 1 ? r.views - 1 : 0)});
    switch (r.budget) {
    case ui::TuneRequest::Budget::AsNow: args.insert(args.end(), {"--budget-from", (dir / "current.json").string()}); break;
    case ui::TuneRequest::Budget::Ms: args.insert(args.end(), {"--budget-ms", fixed(r.ms, 3)}); break;
    case ui::TuneRequest::Budget::MiB: args.insert(args.end(), {"--budget-mib", fixed(r.mib, 3)}); break;
    }
    if (withA) args.insert(args.end(), {"--compare-with", (dir / "A.json").string()});
    if (r.front) args.push_back("--front");
    if (!r.engine.empty()) args.insert(args.end(), {"--engine", r.engine});
    return args;
}

void readTuneProgress(const Json& progress, ui::TuneView& v) {
    const metrics::FigureRow& error = sweep::errorFigure(progress.value("objective", std::string("soft-filtered")));
    v.stage = progress.value("stage", std::string());
    v.done = progress.value("evaluations", 0);
    v.total = progress.value("limit", v.total);
    const Json& best = progress.contains("best") ? progress["best"] : Json();
    v.best = best.is_object() ? "best " + errorText(error, number(best, "error")) + " at " + fixed(number(best, "costMs"), 1) + " ms"
                              : "nothing within the budget yet";
    const double ms = number(progress, "budgetMs"), bytes = number(progress, "budgetBytes");
    v.budget = "budget:";
    // Priced at the tune's size, where the A/B labels price the frame at the viewport's: the size says which.
    if (std::isfinite(ms)) v.budget += " " + fixed(ms, 1) + " ms modelled";
    if (std::isfinite(ms) && v.chart.width > 0) v.budget += " at " + std::to_string(v.chart.width) + "x" + std::to_string(v.chart.height);
    if (std::isfinite(bytes)) v.budget += std::string(std::isfinite(ms) ? " and" : "") + " " + fixed(bytes / kMiB, 1) + " MiB of maps";
    v.chart.errorTitle = error.axisTitle;
    v.chart.costTitle = "modelled cost (ms)";
    v.chart.costName = "modelled ms";
    v.chart.points.clear();
    std::vector<bool> feasible;
    if (progress.contains("points"))
        for (const Json& p : progress["points"]) {
            v.chart.points.push_back(chartPoint(p, "evaluation " + std::to_string(v.chart.points.size() + 1), false, error));
            // "onFront": a --front tune's points within the budget that break a constraint are
            // on its front too (docs/tuning.md#front); older progress files have only "feasible".
            feasible.push_back(p.value("onFront", p.value("feasible", false)));
        }
    const std::size_t evaluations = v.chart.points.size();
    if (progress.contains("input")) v.chart.points.push_back(chartPoint(progress["input"], "current", true, error)), feasible.push_back(false);
    if (progress.contains("references") && progress["references"].contains("A"))
        v.chart.points.push_back(chartPoint(progress["references"]["A"], "A", true, error)), feasible.push_back(false);
    // The title's "N of M points": the evaluations the tune may make, and the marked presets.
    // The simplified tuned point is measured after the search, past the limit: "26 of 25" read wrong.
    v.chart.total = std::max(std::size_t(std::max(v.total, 0)), evaluations) + (v.chart.points.size() - evaluations);
    // The front of what the tune may pick: the feasible evaluations (with --front, those within the budget).
    std::vector<std::pair<double, double>> byTime, byMemory;
    constexpr double kOut = INFINITY;  // an infeasible point: never on the front
    for (std::size_t i = 0; i < v.chart.points.size(); ++i) {
        const ui::SweepPoint& p = v.chart.points[i];
        byTime.emplace_back(feasible[i] ? p.cost : kOut, feasible[i] ? p.error : kOut);
        byMemory.emplace_back(feasible[i] ? p.memory : kOut, feasible[i] ? p.error : kOut);
    }
    const std::vector<bool> t = report::paretoFront(byTime), m = report::paretoFront(byMemory);
    for (std::size_t i = 0; i < v.chart.points.size(); ++i)
        v.chart.points[i].frontByTime = feasible[i] && t[i], v.chart.points[i].frontByMemory = feasible[i] && m[i];
}

std::vector<ui::TuneChange> readExplanation(const Json& explain) {
    std::vector<ui::TuneChange> out;
    if (!explain.contains("changes")) return out;
    for (const Json& c : explain["changes"]) {
        ui::TuneChange change{c.value("text", std::string()), c.value("field", std::string()), c.contains("to") ? c["to"].dump() : "null", {}};
        if (c.contains("with") && c["with"].is_object())
            for (const auto& [path, value] : c["with"].items()) change.with.emplace_back(path, value.dump());
        out.push_back(std::move(change));
    }
    return out;
}

std::pair<std::string, std::string> readSummary(const Json& summary) {
    const metrics::FigureRow& error = sweep::errorFigure(summary.value("objective", std::string("soft-filtered")));
    auto at = [&](const Json& e) {
        return errorText(error, number(e, "error")) + " at " + fixed(number(e, "costMs"), 1) + " ms";
    };
    const Json& tuned = summary["tuned"]["tuned"];
    const Json& input = summary["input"]["tuned"];
    std::string result = "Tuned: " + error.label + " " + at(tuned) + " (current " + at(input) + "), on the tuned views.";
    std::string heldOut;
    if (summary.contains("heldOutHolds") && summary["tuned"].contains("heldOut")) {
        const bool holds = summary["heldOutHolds"].get<bool>();
        heldOut = std::string(holds ? "Holds on the held-out view: " : "Does not hold on the held-out view: ") +
                  errorText(error, number(summary["input"]["heldOut"], "error")) + " current -> " +
                  errorText(error, number(summary["tuned"]["heldOut"], "error")) + " tuned.";
    }
    return {result, heldOut};
}

std::vector<std::pair<std::string, std::string>> tuneObjectives() {
    std::vector<std::pair<std::string, std::string>> out;
    for (const std::string& name : sweep::errorChoices()) out.emplace_back(name, sweep::errorFigure(name).label);
    return out;
}

EditorTune::EditorTune(fs::path executable) : executable_(std::move(executable)) {}

EditorTune::~EditorTune() = default;

void EditorTune::fail(std::vector<std::string> errors) {
    view_.state = ui::TuneView::State::Failed;
    view_.errors = std::move(errors);
}

void EditorTune::start(const ui::TuneRequest& request, const Settings& live, const std::optional<Settings>& a,
                       const fs::path& presetDir) {
    if (running()) return;
    view_ = {};
    view_.total = request.evaluations;
    view_.measuredFrom = live;
    view_.best = "starting: measuring the current settings";
    view_.chart.scene = live.scene;
    view_.chart.width = request.width;
    view_.chart.height = request.height;
    progressTime_ = {};
    try {
        dir_ = newRunFolder("shadowtune-tune");
        view_.folder = (dir_ / "out").string();
        Settings base = live;
        base.scene = absoluteScene(live.scene, presetDir);
        savePresetAtomic(base, dir_ / "base.json");
        savePresetAtomic(base, dir_ / "current.json");
        if (a) {
            Settings as = *a;
            as.scene = base.scene;  // only its method is measured, on the live scene and views
            savePresetAtomic(as, dir_ / "A.json");
        }
    } catch (const std::exception& e) {
        return fail({e.what()});
    }
    std::vector<std::string> args = tuneArguments(request, dir_, a.has_value());
    args.insert(args.begin(), executable_.string());
    std::string error;
    if (!child_.start(args, dir_ / "log.txt", error)) return fail({error});
    view_.state = ui::TuneView::State::Running;
}

void EditorTune::cancel() {
    if (!child_.running() || view_.state == ui::TuneView::State::Cancelling) return;
    child_.interrupt();
    view_.state = ui::TuneView::State::Cancelling;
}

void EditorTune::readProgress() {
    const fs::path file = fs::path(view_.folder) / "progress.json";
    std::error_code ec;
    const fs::file_time_type t = fs::last_write_time(file, ec);
    if (ec || t == progressTime_) return;
    if (const std::optional<Json> j = readJson(file)) {
        readTuneProgress(*j, view_);
        progressTime_ = t;
    }
}

void EditorTune::finish(int status) {
    readProgress();
    const bool cancelling = view_.state == ui::TuneView::State::Cancelling;
    const fs::path out = view_.folder;
    const std::optional<Json> summary = readJson(out / "summary.json"), explain = readJson(out / "explain.json");
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && summary && explain) {
        view_.state = ui::TuneView::State::Done;
        std::tie(view_.result, view_.heldOut) = readSummary(*summary);
        view_.changes = readExplanation(*explain);
        view_.worse.clear();
        if (explain->contains("worse") && (*explain)["worse"].is_array())
            for (const Json& w : (*explain)["worse"]) view_.worse.push_back(w.get<std::string>());
    } else if (cancelling) {
        view_.state = ui::TuneView::State::Cancelled;
    } else {
        std::vector<std::string> errors{"the tune ended with " + exitText(status) + "; its last lines (" +
                                        (dir_ / "log.txt").string() + "):"};
        for (std::string& l : lastLines(dir_ / "log.txt", 4)) errors.push_back(std::move(l));
        fail(std::move(errors));
    }
}

void EditorTune::poll() {
    if (!child_.running()) return;
    view_.elapsedS = child_.elapsedSeconds();
    const ChildRun::Poll p = child_.poll();
    if (p.ended) return finish(*p.ended);
    if (!p.scan) return;
    readProgress();
}

}  // namespace st::app
