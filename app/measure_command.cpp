#include "app/measure_command.h"

#include "app/preset_batch.h"

#include "metrics/measure_session.h"
#include "metrics/metric_images.h"
#include "metrics/metrics_json.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace st::app {
namespace fs = std::filesystem;
namespace {

void writeOutputs(const metrics::PresetMeasurement& m, const std::string& name, const fs::path& dir) {
    makeOutputDir(dir);
    writeImageAtomic(dir / "truth.png", metrics::truthImage(m.samples, m.truth));
    writeImageAtomic(dir / "errors.png", metrics::errorImage(m.accuracy, m.samples.width, m.samples.height));
    writeImageAtomic(dir / "texel-density.png", metrics::densityImage(m.samples));
    if (m.flicker) writeImageAtomic(dir / "flicker.png", metrics::flickerImage(m.flickerStdDev, m.samples));
    writeTextAtomic(dir / "metrics.json", metrics::toJson(m, name).dump(2) + "\n");
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f%%", 100.0 * share);
    return text;
}

void printSummary(const metrics::PresetMeasurement& m, const std::string& name, const fs::path& dir) {
    const metrics::ErrorCounts& a = m.accuracy.all;
    std::printf("%s: %dx%d misclassified %s (false shadow %s, false light %s; gross %zu px), filtered error %.4f, "
                "px/texel median %.2f p95 %.2f",
                name.c_str(), m.samples.width, m.samples.height, percent(a.share(a.misclassified())).c_str(),
                percent(a.share(a.falseShadow())).c_str(), percent(a.share(a.falseLight())).c_str(), a.gross(),
                a.filteredError(), m.density.all.median, m.density.all.p95);
    if (m.flicker) std::printf(", flicker F %s", percent(m.flicker->flipRate).c_str());
    if (m.cost) std::printf(", GPU shadow %.1f ms main %.1f ms", m.cost->gpuShadowMs, m.cost->gpuMainMs);
    std::printf(" | ground truth %.3f s, total %.2f s -> %s\n", m.timings.groundTruthMs / 1000.0,
                m.timings.totalMs / 1000.0, dir.string().c_str());
    std::fflush(stdout);
}

// The GL work of one preset (render, read back, ground truth, cost, flicker); the returned
// writer saves the metrics and images and prints the summary.
PresetWriter measureOne(const MeasureCommandOptions& opt, const fs::path& preset, metrics::MeasureSession& session) {
    Settings s = loadPreset(preset);
    if (opt.width) s.output.width = *opt.width;
    if (opt.height) s.output.height = *opt.height;
    const std::string name = preset.stem().string();
    metrics::MeasureOptions mo;
    mo.costFrames = opt.costFrames;
    mo.flicker = opt.flicker;
    mo.progress = [&name](const std::string& line) {
        std::printf("  %s: %s\n", name.c_str(), line.c_str());
        std::fflush(stdout);
    };
    auto m = std::make_shared<const metrics::PresetMeasurement>(session.measure(s, preset.parent_path(), mo));
    return [m, name, dir = opt.outDir / name] {
        writeOutputs(*m, name, dir);
        printSummary(*m, name, dir);
    };
}

}  // namespace

int runMeasure(const MeasureCommandOptions& opt) {
    return runHeadless({opt.presets, opt.outDir, opt.debugContext}, [&opt]() -> PresetWork {
        auto session = std::make_shared<metrics::MeasureSession>();
        return [&opt, session](const fs::path& preset) { return measureOne(opt, preset, *session); };
    });
}

}  // namespace st::app
