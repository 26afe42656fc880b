// The Sweep panel: up to two axes over sweepable fields, run by the app in the background (it
// shows progress and can be cancelled), and the Pareto chart of the points measured so far;
// hovering a point shows its settings and figures, clicking applies them as one undo step.
#include "renderer/settings/settings_json.h"
#include "ui/document_actions.h"
#include "ui/ui_colours.h"
#include "ui/pareto_plot.h"
#include "ui/panels.h"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace st::ui {

namespace {


bool running(const SweepView* v) {
    return v && (v->state == SweepView::State::Running || v->state == SweepView::State::Cancelling);
}

bool inputText(const char* label, std::string& text) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s", text.c_str());
    if (!ImGui::InputText(label, buf, sizeof buf)) return false;
    text = buf;
    return true;
}

void axisEditor(UiFrame& f, std::size_t i) {
    AxisEdit& e = f.state.compare.axes[i];
    const std::string id = "sweep.axis" + std::to_string(i + 1);
    ImGui::PushID(int(i));
    ImGui::SetNextItemWidth(200.0f);
    const char* preview = e.field.empty() ? "(none)" : e.field.c_str();
    if (ImGui::BeginCombo(("axis " + std::to_string(i + 1)).c_str(), preview)) {
        if (i > 0 && ImGui::Selectable("(none)", e.field.empty())) e.field.clear();
        for (const std::string& path : f.in.sweepableFields)
            if (ImGui::Selectable(path.c_str(), path == e.field)) e.field = path;
        ImGui::EndCombo();
    }
    recordItem(f.state.rects, id + ".field");
    if (!e.field.empty()) {
        ImGui::SameLine();
        ImGui::Checkbox("range", &e.range);
        recordItem(f.state.rects, id + ".range");
        if (e.range) {
            ImGui::SetNextItemWidth(70.0f);
            ImGui::InputDouble("from", &e.from);
            recordItem(f.state.rects, id + ".from");
            ImGui::SameLine();
            ImGui::SetNextItemWidth(70.0f);
            ImGui::InputDouble("to", &e.to);
            recordItem(f.state.rects, id + ".to");
            ImGui::SameLine();
            ImGui::SetNextItemWidth(70.0f);
            ImGui::InputDouble("step", &e.step);
            recordItem(f.state.rects, id + ".step");
        } else {
            ImGui::SetNextItemWidth(300.0f);
            inputText("values", e.list);
            recordItem(f.state.rects, id + ".values");
        }
    }
    ImGui::PopID();
}

void progress(UiFrame& f, const SweepView& v) {
    char text[128];
    const std::string eta = v.etaS < 0.0 ? "-" : std::to_string(long(v.etaS + 0.5)) + " s";
    std::snprintf(text, sizeof text, "%zu/%zu points, %.0f s elapsed, ETA %s%s", v.done, v.total, v.elapsedS,
                  eta.c_str(), v.state == SweepView::State::Cancelling ? " (cancelling)" : "");
    ImGui::ProgressBar(v.total ? float(v.done) / float(v.total) : 0.0f, {-1.0f, 0.0f}, text);
    recordItem(f.state.rects, "sweep.progress");
}

void runControls(UiFrame& f, const ParsedSweep& parsed) {
    const SweepView* v = f.in.sweep;
    if (running(v)) {
        if (ImGui::Button("Cancel")) f.req.sweepCancel = true;
        recordItem(f.state.rects, "sweep.cancel");
        progress(f, *v);
        return;
    }
    ImGui::BeginDisabled(!parsed.request.has_value());
    if (ImGui::Button("Run sweep")) f.req.sweepStart = parsed.request;
    ImGui::EndDisabled();
    recordItem(f.state.rects, "sweep.run");
    if (parsed.request) {
        ImGui::SameLine();
        ImGui::Text("%zu points + current%s, at %dx%d", parsed.points, f.state.compare.a ? " + A" : "",
                    f.state.compare.width, f.state.compare.height);
    }
    if (!v) return;
    switch (v->state) {
    case SweepView::State::Done: ImGui::Text("Done: %zu points in %.0f s", v->done, v->elapsedS); break;
    case SweepView::State::Cancelled: ImGui::Text("Cancelled after %zu of %zu points", v->done, v->total); break;
    case SweepView::State::Failed:
        for (const std::string& e : v->errors) ImGui::TextColored(kErrorColour, "%s", e.c_str());
        recordItem(f.state.rects, "sweep.failed");
        break;
    default: break;
    }
}

// The picked point's assignments on top of the current settings, as one undo step.
void apply(UiFrame& f, const SweepPoint& p) {
    applyEdit(f, withAssignments(f.s, p.assignments));
    f.state.compare.applied = "applied " + p.label;
    f.state.compare.appliedAs = f.s;
}

void tooltip(const SweepPoint& p) {
    ImGui::BeginTooltip();
    ImGui::TextUnformatted(p.label.c_str());
    ImGui::Separator();
    ImGui::TextUnformatted(p.figures.c_str());
    ImGui::TextDisabled("click: apply %s", p.reference ? "its cascades, filter and bias" : "these values");
    ImGui::EndTooltip();
}


void chart(UiFrame& f, const SweepView& v) {
    CompareUiState& c = f.state.compare;
    if (c.appliedAs && *c.appliedAs != f.s) c.applied.clear(), c.appliedAs.reset();  // a later edit
    if (v.points.empty()) return;
    const bool stale = measuredElsewhere(v.measuredFrom, f.s);
    if (stale) {
        ImGui::TextColored(kErrorColour, "Measured from another view: the camera, sun or scene changed since. Run again.");
        recordItem(f.state.rects, "sweep.stale");
        ImGui::PushStyleVar(ImGuiStyleVar_Alpha, ImGui::GetStyle().Alpha * 0.45f);
    }
    const std::string costRadio = "x: " + v.costName;
    ImGui::RadioButton(costRadio.c_str(), !f.state.compare.byMemory) && (f.state.compare.byMemory = false);
    ImGui::SameLine();
    ImGui::RadioButton("x: memory", f.state.compare.byMemory) && (f.state.compare.byMemory = true);
    recordItem(f.state.rects, "sweep.byMemory");
    if (!v.folder.empty()) ImGui::TextDisabled("results and charts: %s", v.folder.c_str());
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const PlotResult r = drawParetoPlot(v, f.state.compare.byMemory, {std::max(avail.x, 200.0f), std::max(avail.y - 24.0f, 160.0f)});
    recordItem(f.state.rects, "sweep.plot");
    for (std::size_t i = 0; i < r.screen.size(); ++i)
        f.state.rects["sweep.point." + std::to_string(i)] = {{r.screen[i].x - 1.0f, r.screen[i].y - 1.0f}, {r.screen[i].x + 1.0f, r.screen[i].y + 1.0f}};
    if (r.hovered >= 0) tooltip(v.points[std::size_t(r.hovered)]);
    if (r.clicked >= 0) apply(f, v.points[std::size_t(r.clicked)]);
    if (stale) ImGui::PopStyleVar();
    if (!c.applied.empty()) {
        ImGui::TextUnformatted(c.applied.c_str());
        recordItem(f.state.rects, "sweep.applied");
    }
}

}  // namespace

void drawSweepPanel(UiFrame& f) {
    CompareUiState& c = f.state.compare;
    if (!c.showSweep) return;
    placeOverRightColumn(f, 510.0f);
    if (ImGui::Begin("Sweep", &c.showSweep)) {
        if (ImGui::Button("Set as A")) setAsA(f);
        recordItem(f.state.rects, "sweep.setA");
        ImGui::SameLine();
        if (ImGui::Button(c.split ? "Split off" : "Split A | live")) toggleSplit(f);
        recordItem(f.state.rects, "sweep.split");
        ImGui::SameLine();
        ImGui::TextDisabled(c.a ? "A is set: marked on the chart" : "A: not set");
        ImGui::Separator();
        const bool busy = running(f.in.sweep);
        ImGui::BeginDisabled(busy);
        for (std::size_t i = 0; i < c.axes.size(); ++i) axisEditor(f, i);
        ImGui::SetNextItemWidth(140.0f);
        int size[2] = {c.width, c.height};
        if (ImGui::InputInt2("size (px)", size)) c.width = size[0], c.height = size[1];
        recordItem(f.state.rects, "sweep.size");
        ImGui::EndDisabled();
        const ParsedSweep parsed = parseSweep(c.axes, f.in.sweepableFields, c.width, c.height);
        for (const std::string& e : parsed.errors) ImGui::TextColored(kErrorColour, "%s", e.c_str());
        if (!parsed.errors.empty()) recordItem(f.state.rects, "sweep.errors");
        runControls(f, parsed);
        if (f.in.sweep) chart(f, *f.in.sweep);
    }
    ImGui::End();
}

}  // namespace st::ui
