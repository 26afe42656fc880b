#include "app/cli/measure_command.h"

#include "app/cost_profile_file.h"

#include "app/images/label_strip.h"
#include "app/images/legend_image.h"
#include "app/cli/preset_batch.h"

#include "metrics/measure_session.h"
#include "metrics/metric_images.h"
#include "metrics/metrics_json.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "report/charts.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::app {
namespace fs = std::filesystem;
namespace {

double mean(const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f%%", 100.0 * share);
    return text;
}

// `shares` in percent against frame index, the first at `firstFrame`.
report::Series frameSeries(const std::string& name, const std::vector<double>& shares, int firstFrame) {
    report::Series s{name, {}, {}};
    for (std::size_t k = 0; k < shares.size(); ++k) {
        s.x.push_back(double(firstFrame) + double(k));
        s.y.push_back(100.0 * shares[k]);
    }
    return s;
}

// path.png: per-frame flip share (frame k against k-1) and misclassification along the path.
report::LineChart pathChart(const metrics::FlickerReport& f, const std::string& name) {
    report::LineChart c;
    c.title = name + ": flicker and misclassification along the camera path (" + std::to_string(f.frames) + " frames)";
    c.subtitle = "mean flip share " + percent(mean(f.flipShareByFrame)) + " (F), mean misclassified " +
                 percent(mean(f.misclassifiedByFrame)) + "; observer fixed, cascade camera on the path";
    c.xLabel = "frame";
    c.yLabel = "share (%)";
    c.series.push_back(frameSeries("flip share (% of sun-facing points)", f.flipShareByFrame, 1));
    c.series.push_back(frameSeries("misclassified (% of sun-facing pixels)", f.misclassifiedByFrame, 0));
    return c;
}

// chartDrawn: whether a PLplot chart has been drawn in this run. Its Pango layouts keep cairo fonts
// alive for good, and cairo_debug_reset_static_data() then aborts on an assertion, so the label
// strips' text caches are released only until the first chart (a second preset after one with a
// path crashed `measure`).
void writeOutputs(const metrics::PresetMeasurement& m, const std::string& name, const fs::path& dir, bool& chartDrawn) {
    makeOutputDir(dir);
    writeImageAtomic(dir / "truth.png", metrics::truthImage(m.samples, m.truth));
    writeImageAtomic(dir / "errors.png",
                     withLegend(metrics::errorImage(m.accuracy, m.samples.width, m.samples.height),
                                "nearest test vs the point truth", metrics::errorLegend(m.accuracy)));
    char title[96];
    std::snprintf(title, sizeof title, "filtered vs the sun's disc (%.2f deg, %d rays), k = %.1f texels",
                  double(m.sun.angularDiameter), m.sun.rays, double(m.settings.measure.artifactTexels));
    writeImageAtomic(dir / "artifacts.png", withLegend(metrics::artifactImage(m.samples, m.softTruth, m.soft), title,
                                                       metrics::artifactLegend(m.softTruth, m.soft)));
    if (!chartDrawn) releaseTextCaches();
    writeImageAtomic(dir / "texel-density.png", metrics::densityImage(m.samples));
    if (m.flicker) {
        writeImageAtomic(dir / "flicker.png", metrics::flickerImage(m.flickerStdDev, m.samples));
        chartDrawn = true;
        report::writeLineChart(pathChart(*m.flicker, name), dir / "path.png", fs::path());
    }
    writeTextAtomic(dir / "metrics.json", metrics::toJson(m, name).dump(2) + "\n");
}

void printSummary(const metrics::PresetMeasurement& m, const std::string& name, const fs::path& dir) {
    const metrics::ErrorCounts& a = m.accuracy.all;
    std::printf("%s: %dx%d misclassified %s (false shadow %s, false light %s; gross %zu px), filtered error %.4f, "
                "px/texel median %.2f p95 %.2f",
                name.c_str(), m.samples.width, m.samples.height, percent(a.share(a.misclassified())).c_str(),
                percent(a.share(a.falseShadow())).c_str(), percent(a.share(a.falseLight())).c_str(), a.gross(),
                a.filteredError(), m.density.all.median, m.density.all.p95);
    const metrics::ArtifactCounts& k = m.soft.all;
    std::printf("; against the sun's disc (%.2f deg, %d rays): filtered error %.4f, acne %s (%zu px), "
                "light bleeding %s (%zu px), peter-panning %s (%zu px), missing caster %s (%zu px), "
                "penumbra %.2f px vs %.2f px true",
                double(m.sun.angularDiameter), m.sun.rays, k.filteredError(), percent(k.share(k.acne)).c_str(), k.acne,
                percent(k.share(k.lightBleeding)).c_str(), k.lightBleeding, percent(k.share(k.peterPanning)).c_str(),
                k.peterPanning, percent(k.share(k.missingCaster)).c_str(), k.missingCaster, m.soft.penumbra.filteredPx,
                m.soft.penumbra.truthPx);
    if (m.flicker) std::printf(", flicker F %s", percent(m.flicker->flipRate).c_str());
    if (m.cost && m.cost->model)
        std::printf(", modelled cost %.1f ms (shadow %.1f, filter %.1f, main %.1f)", m.cost->model->totalMs,
                    m.cost->model->shadowMs, m.cost->model->filterMs, m.cost->model->mainMs);
    if (m.cost)
        std::printf(", GPU shadow %.1f ms (%.1f..%.1f) main %.1f ms (%.1f..%.1f) over %d redrawn frames",
                    m.cost->gpuShadowMs, m.cost->gpuShadowRange.minMs, m.cost->gpuShadowRange.maxMs, m.cost->gpuMainMs,
                    m.cost->gpuMainRange.minMs, m.cost->gpuMainRange.maxMs, m.cost->frames);
    std::printf(" | ground truth %.3f s, soft truth %.3f s, total %.2f s -> %s\n", m.timings.groundTruthMs / 1000.0,
                m.timings.softTruthMs / 1000.0, m.timings.totalMs / 1000.0, dir.string().c_str());
    std::fflush(stdout);
}

// The GL work of one preset (render, read back, ground truth, cost, flicker); the returned
// writer saves the metrics and images and prints the summary.
PresetWriter measureOne(const MeasureCommandOptions& opt, const metrics::CostProfile& profile, const fs::path& preset,
                        metrics::MeasureSession& session, const std::shared_ptr<bool>& chartDrawn) {
    Settings s = loadPreset(preset);
    if (opt.width) s.output.width = *opt.width;
    if (opt.height) s.output.height = *opt.height;
    const std::string name = preset.stem().string();
    metrics::MeasureOptions mo;
    mo.costFrames = opt.costFrames;
    mo.costProfile = &profile;
    mo.flicker = opt.flicker;
    mo.warningLimits = opt.warningLimits;
    mo.progress = [&name](const std::string& line) {
        std::printf("  %s: %s\n", name.c_str(), line.c_str());
        std::fflush(stdout);
    };
    auto m = std::make_shared<const metrics::PresetMeasurement>(session.measure(s, folderOf(preset), mo));
    for (const std::string& w : m->warnings) std::fprintf(stderr, "%s: warning: %s\n", preset.string().c_str(), w.c_str());
    return [m, name, dir = opt.outDir / name, chartDrawn] {
        writeOutputs(*m, name, dir, *chartDrawn);
        printSummary(*m, name, dir);
    };
}

}  // namespace

int runMeasure(const MeasureCommandOptions& opt) {
    const auto profile = loadCostProfileOrReport(opt.costProfile);
    if (!profile) return 1;
    return runHeadless({opt.presets, opt.outDir, opt.debugContext}, [&opt, profile]() -> PresetWork {
        auto session = std::make_shared<metrics::MeasureSession>();
        auto chartDrawn = std::make_shared<bool>(false);
        return [&opt, profile, session, chartDrawn](const fs::path& preset) {
            return measureOne(opt, *profile, preset, *session, chartDrawn);
        };
    });
}

}  // namespace st::app
