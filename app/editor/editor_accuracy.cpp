#include "app/editor/editor_accuracy.h"

#include "metrics/figure_table.h"
#include "metrics/map_warnings.h"
#include "metrics/measure_session.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

namespace st::app {
namespace {

// One core fewer than the machine has for the rays, so the thread drawing the window keeps one.
unsigned rayThreads() {
    const unsigned cores = std::thread::hardware_concurrency();
    return cores > 1 ? cores - 1 : 1;
}

ui::AccuracyCounts toUi(const metrics::ErrorCounts& c) {
    return {c.receivers, c.falseShadowEdge, c.falseShadowGross, c.falseLightEdge, c.falseLightGross, c.filteredError()};
}

const char* phaseName(metrics::JobControl::Phase phase) {
    switch (phase) {
    case metrics::JobControl::Phase::Queued: return "starting";
    case metrics::JobControl::Phase::Bvh: return "building the BVH";
    case metrics::JobControl::Phase::Rays: return "casting rays";
    case metrics::JobControl::Phase::Scoring: return "scoring";
    }
    return "";
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f%%", 100.0 * share);
    return text;
}

// The figure table's Accuracy-panel rows of a still measurement (no density, flicker or cost: the
// rows shown there read only the accuracy and the soft accuracy).
std::vector<ui::FigureLine> figureLines(const metrics::StillAccuracy& a) {
    metrics::PresetMeasurement m;
    m.accuracy.all = a.report.all;
    m.soft.all = a.soft.all;
    m.soft.penumbra = a.soft.penumbra;
    std::vector<ui::FigureLine> out;
    for (const metrics::FigureValue& f : metrics::readFigures(m, metrics::InEditorAccuracy))
        out.push_back({f.row->key, f.row->label, metrics::formatValue(f.row->unit, f.value), f.row->description});
    return out;
}

// The wasted-map warnings of the frame read back (the same rule and limits as `render`).
std::vector<std::string> wastedMaps(const csm::CascadePlan& plan, const Settings& s, const MeasureSamples& samples) {
    FrameStats stats;
    stats.splitBegin = plan.splitRange.begin;
    stats.splitEnd = plan.splitRange.end;
    for (const csm::CascadeFit& c : plan.cascades) {
        CascadeStats cs;
        cs.texelWorldSize = c.texelWorldSize;
        stats.cascades.push_back(cs);
    }
    return metrics::wastedMapWarnings(s, stats, metrics::texelDensity(samples, s.cascades.count),
                                      metrics::farthestSampleDepth(samples, plan.vsView));
}

}  // namespace

EditorAccuracy::EditorAccuracy() : worker_(rayThreads()) {}

bool EditorAccuracy::busy() const {
    const AccuracySchedule::State state = schedule_.state();
    return measurable_ && (state == AccuracySchedule::State::Settling || state == AccuracySchedule::State::Computing);
}

void EditorAccuracy::update(double now, bool wanted, bool rendered, Renderer& r, const Settings& s,
                            const std::shared_ptr<const Scene>& scene) {
    wanted_ = wanted;
    measurable_ = wanted && rendered;
    const bool changed = !wanted || !rendered || !last_ || *last_ != s;
    last_ = s;
    switch (schedule_.update(now, changed)) {
    case AccuracySchedule::Action::Cancel: worker_.cancel(); break;
    case AccuracySchedule::Action::Start: start(r, s, scene); break;
    case AccuracySchedule::Action::None: break;
    }
    collect();
}

// The read-back is the only part on this thread: it needs the GL context, and takes a frame or two.
void EditorAccuracy::start(Renderer& r, const Settings& s, const std::shared_ptr<const Scene>& scene) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
        metrics::StillFrame frame;
        frame.scene = scene;
        frame.samples = pass_.run(r, s, metrics::observerViewProj(s));
        frame.plan = r.plan();
        frame.mapSize = s.cascades.mapSize;
        frame.cascadeCount = s.cascades.count;
        frame.wsEye = s.camera.position;
        pendingWarnings_ = wastedMaps(r.plan(), s, frame.samples);
        frame.sun = metrics::sunDisc(s);
        frame.artifactTexels = s.measure.artifactTexels;
        sun_ = frame.sun;
        worker_.submit(std::move(frame));
    } catch (const std::exception& e) {
        view_.error = e.what();
        schedule_.finished(false);
    }
    readBackSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void EditorAccuracy::collect() {
    std::optional<metrics::AccuracyOutcome> out = worker_.take();
    if (!out) return;
    if (!out->result) {
        view_.error = out->error;
        schedule_.finished(false);
        return;
    }
    const metrics::StillAccuracy& a = *out->result;
    view_.seconds = readBackSeconds_ + out->seconds;
    char timing[160];
    std::snprintf(timing, sizeof timing, "read-back %.2f s, BVH %.2f s, rays %.2f s, sun's disc %.2f s, scoring %.2f s",
                  readBackSeconds_, a.bvhMs / 1000.0, a.raysMs / 1000.0, a.softRaysMs / 1000.0, a.scoreMs / 1000.0);
    view_.timing = timing;
    view_.width = a.overlay.width;
    view_.height = a.overlay.height;
    view_.all = toUi(a.report.all);
    view_.cascades.clear();
    for (const metrics::ErrorCounts& c : a.report.cascades) view_.cascades.push_back(toUi(c));
    view_.beyond = toUi(a.report.beyond);
    view_.warnings = pendingWarnings_;
    const metrics::ArtifactCounts& k = a.soft.all;
    view_.soft = {sun_.angularDiameter, sun_.rays, k.receivers, k.filteredError(), k.acne, k.lightBleeding,
                  k.peterPanning, k.missingCaster, k.edge, a.soft.penumbra.truthPx, a.soft.penumbra.filteredPx};
    view_.figures = figureLines(a);
    overlay_.upload(a.overlay.width, a.overlay.height, a.overlay.pixels);
    classes_ = a.report.classes;
    schedule_.finished(true);
}

ui::AccuracyView EditorAccuracy::view() const {
    using State = ui::AccuracyView::State;
    ui::AccuracyView v;
    switch (schedule_.state()) {
    case AccuracySchedule::State::Settling: v.state = wanted_ ? State::Settling : State::Off; return v;
    case AccuracySchedule::State::Computing: {
        const metrics::AccuracyProgress p = worker_.progress();
        v.state = State::Computing;
        v.progress = p.fraction;
        v.phase = phaseName(p.phase);
        return v;
    }
    case AccuracySchedule::State::Done: v = view_; v.state = State::Done; return v;
    case AccuracySchedule::State::Failed: v.state = State::Failed; v.error = view_.error; return v;
    }
    return v;
}

GLuint EditorAccuracy::overlay() const {
    return schedule_.state() == AccuracySchedule::State::Done ? overlay_.id() : 0;
}

bool EditorAccuracy::finished() const {
    return schedule_.state() == AccuracySchedule::State::Done || schedule_.state() == AccuracySchedule::State::Failed;
}

std::string EditorAccuracy::summary() const {
    const ui::AccuracyView v = view();
    if (v.state == ui::AccuracyView::State::Failed) return "accuracy: failed: " + v.error;
    if (v.state != ui::AccuracyView::State::Done) return "accuracy: not computed";
    const ui::AccuracyCounts& c = v.all;
    const ui::SoftAccuracyCounts& k = v.soft;
    char text[640];
    std::snprintf(text, sizeof text, "accuracy: done in %.2f s (%dx%d): misclassified %s (false shadow %s, "
                  "false light %s; gross %zu px) of %zu sun-facing px, filtered error %.4f; against the sun's disc "
                  "(%.2f deg, %d rays): filtered error %.4f, acne %zu px, light bleeding %zu px, peter-panning %zu px, "
                  "missing caster %zu px [%s]",
                  v.seconds, v.width, v.height, percent(c.share(c.misclassified())).c_str(),
                  percent(c.share(c.falseShadow())).c_str(), percent(c.share(c.falseLight())).c_str(), c.gross(),
                  c.receivers, c.filteredError, double(k.angularDiameter), k.rays, k.filteredError, k.acne,
                  k.lightBleeding, k.peterPanning, k.missingCaster, v.timing.c_str());
    return text;
}

}  // namespace st::app
