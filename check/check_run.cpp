#include "check/check_run.h"

#include <algorithm>
#include <cmath>

namespace st::check {
namespace {

// The figures the report lists: repeatable ones of metrics.json (a time differs between runs).
std::vector<FigureRowResult> figureRows(const SuiteEntry& e, const nlohmann::ordered_json& golden,
                                        const nlohmann::ordered_json& actual, const std::vector<FigureVerdict>& checks) {
    std::vector<FigureRowResult> checked, rest;
    for (const metrics::FigureRow* row : metrics::figuresShown(metrics::InMetricsJson)) {
        if (row->timing) continue;
        FigureRowResult r{row, figureIn(golden, *row), figureIn(actual, *row), std::nullopt};
        for (std::size_t i = 0; i < e.figures.size() && i < checks.size(); ++i)
            if (e.figures[i].row == row) r.verdict = checks[i];
        (r.verdict ? checked : rest).push_back(r);
    }
    // A failing check is what a reader looks for first.
    std::stable_partition(checked.begin(), checked.end(), [](const FigureRowResult& r) { return !r.verdict->pass; });
    checked.insert(checked.end(), rest.begin(), rest.end());
    return checked;
}

bool sameValue(std::optional<double> a, std::optional<double> b) {
    if (!a || !b) return a.has_value() == b.has_value();
    return *a == *b || (std::isnan(*a) && std::isnan(*b));
}

}  // namespace

const char* statusName(Status s) {
    switch (s) {
        case Status::Pass: return "PASS";
        case Status::Failed: return "FAILED";
        case Status::GoldenMissing: return "GOLDEN_MISSING";
        case Status::RendererMismatch: return "RENDERER_MISMATCH";
        case Status::Error: return "ERROR";
        case Status::New: return "NEW";
        case Status::Updated: return "UPDATED";
        case Status::Unchanged: return "UNCHANGED";
    }
    return "?";
}

bool isFailure(Status s) {
    return s == Status::Failed || s == Status::GoldenMissing || s == Status::RendererMismatch || s == Status::Error;
}

std::optional<double> figureIn(const nlohmann::ordered_json& figures, const metrics::FigureRow& row) {
    const nlohmann::ordered_json::json_pointer p(metrics::jsonPointer(row.key));
    if (!figures.contains(p)) return std::nullopt;
    const auto& v = figures.at(p);
    if (!v.is_number()) return std::nullopt;
    return v.get<double>();
}

PresetResult judge(const SuiteEntry& e, const Actual& actual, const std::optional<Golden>& golden) {
    PresetResult r;
    r.name = e.name;
    r.preset = e.preset.string();
    r.note = e.note;
    r.imageTolerance = e.image.describe();
    if (!golden) {
        r.status = Status::GoldenMissing;
        r.message = "no golden (run with --update to make one, then review it)";
        r.figures = figureRows(e, {}, actual.figures, {});
        return r;
    }
    r.goldenDir = golden->dir.string();
    for (const FigureTolerance& t : e.figures)
        r.checks.push_back(checkFigure(t, figureIn(golden->figures, *t.row), figureIn(actual.figures, *t.row)));
    r.figures = figureRows(e, golden->figures, actual.figures, r.checks);
    r.image = diffImages(actual.image, golden->image, e.image);
    if (golden->meta.settingsHash != actual.meta.settingsHash)
        r.notes.push_back("the settings differ from the golden's (hash " + golden->meta.settingsHash + " -> " +
                          actual.meta.settingsHash + ")");
    const bool otherRenderer = golden->meta.renderer != actual.meta.renderer;
    if (otherRenderer)
        r.notes.push_back("the golden was made by '" + golden->meta.renderer + "', this run by '" + actual.meta.renderer + "'");
    std::vector<std::string> failed;
    if (!r.image->pass) failed.push_back("image: " + r.image->summary() + " (allowed " + r.imageTolerance + ")");
    for (const FigureVerdict& v : r.checks)
        if (!v.pass) failed.push_back(v.message);
    if (otherRenderer && e.onRendererMismatch == OnRendererMismatch::Fail) {
        r.status = Status::RendererMismatch;
        r.message = r.notes.back() + " (the suite's on_renderer_mismatch is \"fail\"; keep goldens per renderer in "
                    "GOLDEN/" + rendererSlug(actual.meta.renderer) + "/)";
        return r;
    }
    r.status = failed.empty() ? Status::Pass : Status::Failed;
    for (const std::string& f : failed) r.message += (r.message.empty() ? "" : "; ") + f;
    if (r.message.empty()) r.message = r.image->summary();
    return r;
}

PresetResult updateVerdict(const SuiteEntry& e, const Actual& actual, const std::optional<Golden>& golden) {
    PresetResult r = judge(e, actual, golden);
    if (!golden) {
        r.status = Status::New;
        r.message = "new golden";
        return r;
    }
    r.notes.clear();
    for (const FigureRowResult& f : r.figures)
        if (!sameValue(f.golden, f.actual)) {
            std::string line = f.row->label + " " + metrics::formatValue(f.row->unit, f.golden) + " -> " +
                               metrics::formatValue(f.row->unit, f.actual);
            if (f.golden && f.actual) line += " (" + metrics::formatDelta(f.row->unit, *f.actual - *f.golden) + ")";
            r.notes.push_back(line);
        }
    if (actual.image.pixels != golden->image.pixels || actual.image.width != golden->image.width)
        r.notes.push_back("image: " + r.image->summary());
    if (golden->meta.renderer != actual.meta.renderer)
        r.notes.push_back("renderer: '" + golden->meta.renderer + "' -> '" + actual.meta.renderer + "'");
    if (golden->meta.settingsHash != actual.meta.settingsHash)
        r.notes.push_back("settings hash: " + golden->meta.settingsHash + " -> " + actual.meta.settingsHash);
    // Measured times differ between runs: only the repeatable figures count as a change.
    r.status = r.notes.empty() ? Status::Unchanged : Status::Updated;
    r.message = r.status == Status::Unchanged ? "unchanged" : std::to_string(r.notes.size()) + " changed";
    return r;
}

int exitCodeOf(const std::vector<PresetResult>& results) {
    return std::any_of(results.begin(), results.end(), [](const PresetResult& r) { return isFailure(r.status); }) ? 1 : 0;
}

std::vector<const PresetResult*> failuresFirst(const std::vector<PresetResult>& results) {
    std::vector<const PresetResult*> out;
    for (const PresetResult& r : results) out.push_back(&r);
    std::stable_partition(out.begin(), out.end(), [](const PresetResult* r) { return isFailure(r->status); });
    return out;
}

}  // namespace st::check
