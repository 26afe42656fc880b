#include "app/editor/editor_sweep.h"

#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "report/pareto.h"
#include "sweep/sweep_run.h"

#include <sys/wait.h>  // WIFEXITED

#include <cmath>

namespace st::app {
namespace fs = std::filesystem;

namespace {


// The hover text: the figure table's Sweep-panel rows, one "label value" line each.
std::string figureLines(const sweep::PointResult& r, const metrics::FigureTable& table) {
    std::string text;
    for (const metrics::FigureRow* row : metrics::figuresShown(metrics::InEditorSweep, table)) {
        const double v = r.figure(row->key);
        text += (text.empty() ? "" : "\n") + row->label + " " +
                metrics::formatValue(row->unit, std::isfinite(v) ? std::optional<double>(v) : std::nullopt);
    }
    return text;
}

// A reference's method (what the sweep measured of it: sweep_spec.cpp onBase) as assignments.
std::vector<std::pair<std::string, std::string>> methodAssignments(const nlohmann::ordered_json& preset) {
    std::vector<std::pair<std::string, std::string>> out;
    const Settings s = fromJson(nlohmann::json::parse(preset.dump()), "sweep point");
    for (const FieldInfo& f : fieldTable()) {
        const std::string_view path = f.path;
        if (path.rfind("cascades.", 0) == 0 || path.rfind("filter.", 0) == 0 || path.rfind("bias.", 0) == 0)
            out.emplace_back(std::string(path), fieldValueToJson(f, f.get(s)).dump());
    }
    return out;
}

}  // namespace

fs::path writeEditorSweep(const fs::path& dir, const ui::SweepRequest& request, const Settings& base,
                          const std::optional<Settings>& a, const fs::path& presetDir) {
    Settings b = base;
    b.scene = absoluteScene(base.scene, presetDir);
    savePresetAtomic(b, dir / "base.json");
    savePresetAtomic(b, dir / "current.json");
    nlohmann::ordered_json refs = nlohmann::ordered_json::array({"current.json"});
    if (a) {
        Settings as = *a;
        as.scene = b.scene;  // only its cascades, filter and bias are measured, on the base
        savePresetAtomic(as, dir / "A.json");
        refs.push_back("A.json");
    }
    nlohmann::ordered_json axes = nlohmann::ordered_json::array();
    for (const ui::SweepAxisRequest& ax : request.axes) {
        nlohmann::ordered_json j{{"field", ax.field}};
        j[ax.range ? "range" : "values"] = nlohmann::ordered_json::parse(ax.values.dump());
        axes.push_back(std::move(j));
    }
    // A still frame: the chart is error against cost of what the camera sees now, and a camera
    // path would multiply the time of every point by its frames.
    const nlohmann::ordered_json sweep{{"version", sweep::kSweepVersion},
                                       {"notes", "written by the editor's Sweep panel"},
                                       {"base", "base.json"},
                                       {"set", {{"output.width", request.width}, {"output.height", request.height}, {"path.frames", 0}}},
                                       {"axes", axes},
                                       {"references", refs}};
    const fs::path file = dir / "sweep.json";
    writeTextAtomic(file, sweep.dump(2) + "\n");
    return file;
}

ui::SweepPoint chartPoint(const sweep::PointResult& r, const std::vector<std::string>& axisFields) {
    ui::SweepPoint p;
    p.label = r.label;
    p.reference = r.reference;
    const sweep::ReportOptions chosen;  // the chart's figures: those `shadowtune sweep` charts by default
    const auto shown = [&](const metrics::FigureRow& row) { return metrics::shown(row.unit, r.figure(row.key)); };
    p.cost = shown(sweep::costFigure(chosen.cost));
    p.memory = shown(sweep::costFigure(sweep::kMemoryChoice));
    p.error = shown(sweep::errorFigure(chosen.error));
    p.figures = figureLines(r, metrics::figureTable());
    if (r.reference) {
        p.assignments = methodAssignments(r.settings);
    } else {
        for (std::size_t i = 0; i < axisFields.size() && i < r.axisValues.size(); ++i)
            p.assignments.emplace_back(axisFields[i], r.axisValues[i]);
    }
    return p;
}

std::vector<ui::SweepPoint> chartPoints(const std::vector<sweep::PointResult>& results,
                                        const std::vector<std::string>& axisFields) {
    std::vector<ui::SweepPoint> points;
    std::vector<std::pair<double, double>> byTime, byMemory;
    for (const sweep::PointResult& r : results) {
        points.push_back(chartPoint(r, axisFields));
        byTime.push_back({points.back().cost, points.back().error});
        byMemory.push_back({points.back().memory, points.back().error});
    }
    const std::vector<bool> t = report::paretoFront(byTime), m = report::paretoFront(byMemory);
    for (std::size_t i = 0; i < points.size(); ++i) points[i].frontByTime = t[i], points[i].frontByMemory = m[i];
    return points;
}

EditorSweep::EditorSweep(fs::path executable, int costFrames)
    : executable_(std::move(executable)), costFrames_(costFrames) {}

EditorSweep::~EditorSweep() = default;

void EditorSweep::fail(std::vector<std::string> errors) {
    view_.state = ui::SweepView::State::Failed;
    view_.errors = std::move(errors);
}

void EditorSweep::start(const ui::SweepRequest& request, const Settings& live, const std::optional<Settings>& a,
                        const fs::path& presetDir) {
    if (running()) return;
    view_ = {};
    const sweep::ReportOptions chosen;
    const metrics::FigureRow& cost = sweep::costFigure(chosen.cost);
    view_.costTitle = cost.axisTitle;
    view_.costName = cost.label;
    view_.memoryTitle = sweep::costFigure(sweep::kMemoryChoice).axisTitle;
    view_.errorTitle = sweep::errorFigure(chosen.error).axisTitle;
    view_.width = request.width;
    view_.height = request.height;
    view_.scene = live.scene;
    view_.measuredFrom = live;
    readCount_ = 0;
    try {
        dir_ = newRunFolder("shadowtune-sweep");
        view_.folder = (dir_ / "out").string();
        const fs::path file = writeEditorSweep(dir_, request, live, a, presetDir);
        spec_ = sweep::loadSweep(file);  // refused here, in the editor, with the reader's messages
        const std::vector<sweep::Point> points = sweep::expandPoints(*spec_);
        manifest_ = sweep::manifestOf(*spec_, points, "");
        view_.total = points.size();
    } catch (const SettingsError& e) {
        return fail(e.messages());
    } catch (const std::exception& e) {
        return fail({e.what()});
    }
    const std::vector<std::string> args = {executable_.string(), "sweep", (dir_ / "sweep.json").string(), "--out",
                                           view_.folder, "--frames", std::to_string(costFrames_)};
    std::string error;
    if (!child_.start(args, dir_ / "log.txt", error)) return fail({error});
    view_.state = ui::SweepView::State::Running;
}

void EditorSweep::cancel() {
    if (!child_.running() || view_.state == ui::SweepView::State::Cancelling) return;
    child_.interrupt();
    view_.state = ui::SweepView::State::Cancelling;
}

void EditorSweep::readNewPoints() {
    const fs::path points = fs::path(view_.folder) / "points";
    std::size_t found = 0;
    std::error_code ec;
    for (const std::string& id : manifest_->pointIds) found += fs::exists(points / (id + ".json"), ec) ? 1 : 0;
    view_.done = found;
    if (found == readCount_) return;
    try {
        const std::vector<sweep::PointResult> results = sweep::readPoints(view_.folder, *manifest_);
        view_.points = chartPoints(results, manifest_->axisFields);
        readCount_ = results.size();
    } catch (const std::exception&) {
        // A file renamed into place between the scan and the read: the next scan reads it.
    }
}

void EditorSweep::finish(int status) {
    readNewPoints();
    const bool cancelling = view_.state == ui::SweepView::State::Cancelling;
    // A child stopped by the cancel exits 130; 0 means it measured every point (Cancel came after
    // the last one, while it wrote the charts), so the run is done, not "cancelled after 11 of 11".
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        view_.state = ui::SweepView::State::Done;
    } else if (cancelling) {
        view_.state = ui::SweepView::State::Cancelled;
    } else {
        std::vector<std::string> errors{"the sweep ended with " + exitText(status) + "; its last lines (" +
                                        (dir_ / "log.txt").string() + "):"};
        for (std::string& l : lastLines(dir_ / "log.txt", 6)) errors.push_back(std::move(l));
        fail(std::move(errors));
    }
    view_.etaS = -1.0;
}

void EditorSweep::poll() {
    if (!child_.running()) return;
    view_.elapsedS = child_.elapsedSeconds();
    const ChildRun::Poll p = child_.poll();
    if (p.ended) return finish(*p.ended);
    if (!p.scan) return;
    readNewPoints();
    if (view_.done > 0)
        view_.etaS = view_.elapsedS / double(view_.done) * double(view_.total - view_.done);
}

}  // namespace st::app
