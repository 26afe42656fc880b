// The Tune panel (docs/editor.md#tune): a budget ("as cheap as now", ms or MiB), an objective,
// Go and Cancel; while the app's `shadowtune tune` child runs, its progress and the points
// measured so far on a Pareto chart with the current settings and A marked; at the end the
// explanation, each line applicable alone, and the tuned settings, each apply one undo step.
#include "renderer/export/engine_knobs.h"
#include "ui/document_actions.h"
#include "ui/ui_colours.h"
#include "ui/panels.h"
#include "ui/pareto_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace st::ui {

std::string tuneObjectiveFor(const std::string& adviceRule) {
    if (adviceRule == "acne" || adviceRule == "peter-panning") return adviceRule;
    return "misclassified";  // coarse texels: shadows of the wrong shape, counted per pixel
}

void openTuneFor(TuneUiState& t, const std::string& adviceRule) {
    t.show = true;
    t.edit.objective = tuneObjectiveFor(adviceRule);
}

namespace {


bool running(const TuneView* v) {
    return v && (v->state == TuneView::State::Running || v->state == TuneView::State::Cancelling);
}

// What is wrong with the panel's fields, or "" when Go may be pressed.
std::string requestProblem(const TuneRequest& r) {
    if (r.budget == TuneRequest::Budget::Ms && !(r.ms > 0.0)) return "the budget in ms must be above 0";
    if (r.budget == TuneRequest::Budget::MiB && !(r.mib > 0.0)) return "the budget in MiB must be above 0";
    if (r.evaluations < 4 || r.evaluations > 400) return "evaluations: 4 .. 400";
    if (r.views < 1 || r.views > 16) return "views: 1 .. 16";
    if (r.width < 16 || r.height < 16 || r.width > 4096 || r.height > 4096) return "size: 16 .. 4096 px each side";
    return "";
}

void budgetFields(UiFrame& f) {
    TuneRequest& r = f.state.tune.edit;
    int kind = int(r.budget);
    ImGui::TextUnformatted("Budget");
    ImGui::SameLine();
    ImGui::RadioButton("as cheap as now", &kind, int(TuneRequest::Budget::AsNow));
    recordItem(f.state.rects, "tune.budget.now");
    ImGui::SameLine();
    ImGui::RadioButton("ms", &kind, int(TuneRequest::Budget::Ms));
    recordItem(f.state.rects, "tune.budget.ms");
    ImGui::SameLine();
    ImGui::RadioButton("MiB", &kind, int(TuneRequest::Budget::MiB));
    recordItem(f.state.rects, "tune.budget.mib");
    r.budget = TuneRequest::Budget(kind);
    if (r.budget == TuneRequest::Budget::Ms) {
        ImGui::SetNextItemWidth(100.0f);
        ImGui::InputDouble("modelled ms at most", &r.ms, 0.0, 0.0, "%.1f");
        recordItem(f.state.rects, "tune.ms");
    } else if (r.budget == TuneRequest::Budget::MiB) {
        ImGui::SetNextItemWidth(100.0f);
        ImGui::InputDouble("MiB of maps at most", &r.mib, 0.0, 0.0, "%.1f");
        recordItem(f.state.rects, "tune.mib");
    } else {
        ImGui::TextDisabled("the current settings' modelled cost and map memory, on the same views");
    }
}

void objectiveField(UiFrame& f) {
    TuneRequest& r = f.state.tune.edit;
    std::string preview = r.objective;
    for (const auto& [name, label] : f.in.tuneObjectives)
        if (name == r.objective) preview = label;
    ImGui::SetNextItemWidth(260.0f);
    if (ImGui::BeginCombo("objective", preview.c_str())) {
        for (const auto& [name, label] : f.in.tuneObjectives)
            if (ImGui::Selectable(label.c_str(), name == r.objective)) r.objective = name;
        ImGui::EndCombo();
    }
    recordItem(f.state.rects, "tune.objective");
}

void searchFields(UiFrame& f) {
    TuneRequest& r = f.state.tune.edit;
    ImGui::SetNextItemWidth(100.0f);
    ImGui::InputInt("evaluations", &r.evaluations);
    recordItem(f.state.rects, "tune.evaluations");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80.0f);
    ImGui::InputInt("views", &r.views);
    recordItem(f.state.rects, "tune.views");
    ImGui::SetNextItemWidth(140.0f);
    int size[2] = {r.width, r.height};
    if (ImGui::InputInt2("size (px)", size)) r.width = size[0], r.height = size[1];
    recordItem(f.state.rects, "tune.size");
    ImGui::Checkbox("front down to the cheapest", &r.front);
    recordItem(f.state.rects, "tune.front");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Keep a quarter of the evaluations for a descent from the tuned settings to the\n"
                          "cheapest ones: the chart's front then runs from there to the budget, each\n"
                          "point judged on the objective alone (docs/tuning.md#front).");
}

void progress(UiFrame& f, const TuneView& v) {
    char text[192];
    std::snprintf(text, sizeof text, "%d/%d evaluations, %.0f s; %s%s", v.done, v.total, v.elapsedS, v.best.c_str(),
                  v.state == TuneView::State::Cancelling ? " (cancelling)" : "");
    ImGui::ProgressBar(v.total ? float(std::min(v.done, v.total)) / float(v.total) : 0.0f, {-1.0f, 0.0f}, text);
    recordItem(f.state.rects, "tune.progress");
    if (v.stage == "explaining") ImGui::TextDisabled("explaining each change (measuring it alone and in the tuned settings)...");
}

void runControls(UiFrame& f, const std::string& problem) {
    const TuneView* v = f.in.tune;
    if (running(v)) {
        if (ImGui::Button("Cancel")) f.req.tuneCancel = true;
        recordItem(f.state.rects, "tune.cancel");
        ImGui::SameLine();
        ImGui::TextDisabled("keeps what was measured");
        progress(f, *v);
        return;
    }
    if (f.state.engine.engine)
        ImGui::TextDisabled("Tunes in %s's knobs only (Settings > Engine).", xport::engineName(*f.state.engine.engine).c_str());
    ImGui::BeginDisabled(!problem.empty());
    if (ImGui::Button("Go")) {
        f.req.tuneStart = f.state.tune.edit;
        if (f.state.engine.engine) f.req.tuneStart->engine = xport::engineName(*f.state.engine.engine);
    }
    ImGui::EndDisabled();
    recordItem(f.state.rects, "tune.go");
    if (!problem.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(kErrorColour, "%s", problem.c_str());
    }
    if (!v) return;
    if (!v->budget.empty()) ImGui::TextDisabled("%s", v->budget.c_str());
    switch (v->state) {
    case TuneView::State::Cancelled:
        ImGui::Text("Cancelled after %d of %d evaluations; %s", v->done, v->total, v->best.c_str());
        break;
    case TuneView::State::Failed:
        for (const std::string& e : v->errors) ImGui::TextColored(kErrorColour, "%s", e.c_str());
        recordItem(f.state.rects, "tune.failed");
        break;
    default: break;
    }
}


void applyChanges(UiFrame& f, const std::vector<const TuneChange*>& changes, std::string what) {
    std::vector<std::pair<std::string, std::string>> assignments;
    for (const TuneChange* c : changes) {
        assignments.insert(assignments.end(), c->with.begin(), c->with.end());
        assignments.emplace_back(c->path, c->valueJson);
    }
    applyEdit(f, withAssignments(f.s, assignments));
    f.state.tune.applied = "applied " + std::move(what);
    f.state.tune.appliedAs = f.s;
}

void explanation(UiFrame& f, const TuneView& v) {
    if (v.state != TuneView::State::Done) return;
    ImGui::Separator();
    ImGui::TextWrapped("%s", v.result.c_str());
    recordItem(f.state.rects, "tune.result");
    if (!v.heldOut.empty()) ImGui::TextWrapped("%s", v.heldOut.c_str());
    for (const std::string& w : v.worse) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
        ImGui::TextWrapped("Worse than the current settings: %s", w.c_str());
        ImGui::PopStyleColor();
    }
    if (!v.worse.empty()) recordItem(f.state.rects, "tune.worse");
    if (v.changes.empty()) {
        ImGui::TextDisabled("Nothing within the budget beat the current settings.");
        return;
    }
    std::vector<const TuneChange*> all;
    for (const TuneChange& c : v.changes) all.push_back(&c);
    if (ImGui::Button("Apply tuned")) applyChanges(f, all, "the tuned settings");
    recordItem(f.state.rects, "tune.apply");
    ImGui::SameLine();
    ImGui::TextDisabled("each change alone:");
    for (std::size_t i = 0; i < v.changes.size(); ++i) {
        ImGui::PushID(int(i));
        if (ImGui::SmallButton("Apply")) applyChanges(f, {&v.changes[i]}, v.changes[i].path + " alone");
        recordItem(f.state.rects, "tune.change." + std::to_string(i));
        ImGui::SameLine();
        const bool worse = v.changes[i].line.rfind("(!) ", 0) == 0;  // tune_explain.cpp marks a worse artifact
        if (worse) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
        ImGui::TextWrapped("%s", v.changes[i].line.c_str());
        if (worse) ImGui::PopStyleColor();
        ImGui::PopID();
    }
}

void chart(UiFrame& f, const TuneView& v) {
    if (v.chart.points.empty()) return;
    const bool stale = measuredElsewhere(v.measuredFrom, f.s);
    if (stale) {
        ImGui::TextColored(kErrorColour, "Measured from another view: the camera, sun or scene changed since.");
        recordItem(f.state.rects, "tune.stale");
        ImGui::PushStyleVar(ImGuiStyleVar_Alpha, ImGui::GetStyle().Alpha * 0.45f);
    }
    const float reserve = v.state == TuneView::State::Done ? 150.0f + 22.0f * float(v.changes.size()) : 24.0f;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const PlotResult r = drawParetoPlot(v.chart, false, {std::max(avail.x, 200.0f), std::max(avail.y - reserve, 160.0f)});
    recordItem(f.state.rects, "tune.plot");
    if (r.hovered >= 0) {
        const SweepPoint& p = v.chart.points[std::size_t(r.hovered)];
        ImGui::BeginTooltip();
        ImGui::TextUnformatted(p.label.c_str());
        ImGui::Separator();
        ImGui::TextUnformatted(p.figures.c_str());
        ImGui::EndTooltip();
    }
    if (stale) ImGui::PopStyleVar();
}

}  // namespace

void drawTunePanel(UiFrame& f) {
    TuneUiState& t = f.state.tune;
    if (t.appliedAs && *t.appliedAs != f.s) t.applied.clear(), t.appliedAs.reset();  // a later edit
    if (!t.show) return;
    placeOverRightColumn(f, 540.0f);
    if (ImGui::Begin("Tune", &t.show)) {
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        f.state.rects["window.Tune"] = {pos, {pos.x + size.x, pos.y + size.y}};
        const TuneView* v = f.in.tune;
        ImGui::BeginDisabled(running(v));
        budgetFields(f);
        objectiveField(f);
        searchFields(f);
        ImGui::EndDisabled();
        runControls(f, requestProblem(t.edit));
        if (v && !v->folder.empty()) ImGui::TextDisabled("results: %s", v->folder.c_str());
        if (v) chart(f, *v);
        if (v) explanation(f, *v);
        if (!t.applied.empty()) {
            ImGui::TextUnformatted(t.applied.c_str());
            recordItem(f.state.rects, "tune.applied");
        }
    }
    ImGui::End();
}

}  // namespace st::ui
