#include "app/cli/compare_command.h"

#include "renderer/settings/method_on_view.h"

#include "app/images/compare_images.h"
#include "app/cli/preset_batch.h"

#include "metrics/compare.h"
#include "metrics/measure_session.h"
#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::app {
namespace fs = std::filesystem;
namespace {

struct Side {
    std::string tag;   // "A" or "B"
    std::string name;  // file stem
    fs::path file;
    fs::path dir;      // resolves the scene's relative path
    Settings settings;
};


void checkMerged(const Side& b, const Side& a) {
    std::vector<std::string> problems = validate(b.settings);
    if (problems.empty()) return;
    for (std::string& p : problems) p = b.file.string() + " on the view of " + a.file.string() + ": " + p;
    throw SettingsError(problems);
}

// Both presets, read and made comparable: one output size and the shaded view.
std::pair<Side, Side> loadSides(const CompareOptions& opt) {
    Side a{"A", opt.a.stem().string(), opt.a, folderOf(opt.a), loadPreset(opt.a)};
    Side b{"B", opt.b.stem().string(), opt.b, folderOf(opt.b), loadPreset(opt.b)};
    if (!opt.keepBScene) {
        b.settings = methodOnView(b.settings, a.settings);
        b.dir = a.dir;
    }
    if (opt.width) {
        a.settings.output.width = *opt.width;
        a.settings.output.height = *opt.height;
    }
    b.settings.output = a.settings.output;
    a.settings.output.view = b.settings.output.view = View::Shaded;
    checkMerged(b, a);
    return {a, b};
}

struct Measured {
    metrics::PresetMeasurement m;
    Rgba8Image shaded;
};

Measured measureSide(metrics::MeasureSession& session, const Side& side, const CompareOptions& opt) {
    metrics::MeasureOptions mo;
    mo.costFrames = opt.costFrames;
    mo.progress = [&side](const std::string& line) {
        std::printf("  %s %s: %s\n", side.tag.c_str(), side.name.c_str(), line.c_str());
        std::fflush(stdout);
    };
    Measured r{session.measure(side.settings, side.dir, mo), {}};
    Renderer& renderer = *session.entryFor(side.settings, side.dir).renderer;
    renderer.render(side.settings);  // the path replay left another cascade camera's maps
    r.shaded = {renderer.width(), renderer.height(), renderer.readRgba8()};
    return r;
}

// The label under a picture: the preset and its headline figures.
Strip headline(const Side& side, const std::vector<metrics::CompareFigure>& figures, bool isA) {
    const auto find = [&](const std::string& key) -> const metrics::CompareFigure& {
        for (const metrics::CompareFigure& f : figures)
            if (f.key == key) return f;
        throw std::logic_error("no figure " + key);
    };
    const auto raw = [&](const std::string& key) { return (isA ? find(key).a : find(key).b).value_or(0.0); };
    const auto text = [&](const std::string& key) {
        const metrics::CompareFigure& f = find(key);
        return metrics::formatValue(f.unit, isA ? f.a : f.b);
    };
    char gpu[64];
    std::snprintf(gpu, sizeof gpu, "GPU shadow %.2f + main %.2f ms", raw("cost.gpuShadowMs"), raw("cost.gpuMainMs"));
    const auto line = [&](const std::string& key) { return find(key).label + " " + text(key); };
    return {{side.tag + ": " + side.name, std::nullopt, true},
            {line("accuracy.misclassified")},
            {line("accuracy.filteredError")},
            {gpu},
            {line("cost.shadowMapBytes")}};
}

bool sameView(const Settings& a, const Settings& b) {
    return a.scene == b.scene && a.ground == b.ground && a.camera == b.camera && a.output == b.output;
}

struct Outputs {
    Rgba8Image sideBySide, split;
    std::optional<Rgba8Image> diff;
    std::string json, table;
};

Outputs compose(const Side& a, const Side& b, const Measured& ma, const Measured& mb, bool sharedView) {
    const auto figures = metrics::compareFigures(ma.m, mb.m);
    std::optional<metrics::ShadowDiff> diff;
    if (sameView(a.settings, b.settings)) diff = metrics::shadowDiff(ma.m.samples, mb.m.samples);
    const metrics::CompareNames names{a.name, b.name, a.file.string(), b.file.string(), sharedView};
    const Strip la = headline(a, figures, true), lb = headline(b, figures, false);
    Outputs o{sideBySideImage(ma.shaded, mb.shaded, la, lb),
              splitImage(ma.shaded, mb.shaded, {la[0], la[1]}, {lb[0], lb[1]}),
              std::nullopt,
              metrics::compareJson(names, figures, ma.m, diff).dump(2) + "\n",
              metrics::compareTable(names, figures, diff)};
    if (diff) o.diff = shadowDiffImage(*diff, a.name, b.name);
    return o;
}

void write(const Outputs& o, const fs::path& dir) {
    writeImageAtomic(dir / "side-by-side.png", o.sideBySide);
    writeImageAtomic(dir / "split.png", o.split);
    if (o.diff) writeImageAtomic(dir / "shadow-diff.png", *o.diff);
    writeTextAtomic(dir / "compare.json", o.json);
    std::printf("%s", o.table.c_str());
    if (!o.diff) std::printf("shadow-diff.png not written: A and B see different views (--keep-b-scene)\n");
    std::printf("wrote %s/{side-by-side.png,split.png%s,compare.json}\n", dir.string().c_str(),
                o.diff ? ",shadow-diff.png" : "");
    std::fflush(stdout);
}

// The GL part: a context, both measurements, and the check that GL reported nothing serious.
Outputs measureBoth(const CompareOptions& opt, const Side& a, const Side& b) {
    const std::unique_ptr<HeadlessContext> ctx = HeadlessContext::create(opt.debugContext);
    if (opt.debugContext) gpu::enableDebugOutput();
    metrics::MeasureSession session;
    const Measured ma = measureSide(session, a, opt);
    const Measured mb = measureSide(session, b, opt);
    if (opt.debugContext && gpu::seriousDebugMessageCount() > 0)
        throw std::runtime_error("GL debug output reported errors (see above)");
    return compose(a, b, ma, mb, !opt.keepBScene);
}

}  // namespace

int runCompare(const CompareOptions& opt) {
    struct ReleaseAtEnd {
        ~ReleaseAtEnd() { releaseTextCaches(); }
    } release;
    std::optional<std::pair<Side, Side>> sides;
    try {
        sides = loadSides(opt);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    try {
        makeOutputDir(opt.outDir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
    try {
        write(measureBoth(opt, sides->first, sides->second), opt.outDir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\nnothing compared\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace st::app
