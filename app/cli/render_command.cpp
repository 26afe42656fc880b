#include "app/cli/render_command.h"

#include "app/cost_profile_file.h"
#include "app/cli/preset_batch.h"
#include "app/scene_preset.h"

#include "metrics/cost_model.h"
#include "metrics/measure_session.h"
#include "renderer/image/image_io.h"
#include "renderer/render/device.h"
#include "renderer/render/frame_stats_text.h"
#include "renderer/render/renderer.h"
#include "renderer/render/scene_cache.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/enum_names.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace st::app {
namespace fs = std::filesystem;
namespace {

void checkDeviceLimits(const Settings& s, const fs::path& preset) {
    const int maxSize = deviceLimits().maxTextureSize;
    if (s.cascades.mapSize > maxSize)
        throw std::runtime_error(preset.string() + ": cascades.mapSize: " +
                                 std::to_string(s.cascades.mapSize) +
                                 " exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
    // The atlas is wider than any of its tiles: check the textures the layout allocates.
    for (const csm::MapTexture& t : csm::planStorage(s.cascades).textures)
        if (t.width > maxSize || t.height > maxSize)
            throw std::runtime_error(preset.string() + ": cascades.storage: a " + std::to_string(t.width) + "x" +
                                     std::to_string(t.height) + " shadow texture exceeds GL_MAX_TEXTURE_SIZE " +
                                     std::to_string(maxSize));
    if (s.output.width > maxSize || s.output.height > maxSize)
        throw std::runtime_error(preset.string() + ": output size exceeds GL_MAX_TEXTURE_SIZE " +
                                 std::to_string(maxSize));
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// "12.34 ms (min 11.00, max 14.00)" of the frames' values.
std::string spread(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    char text[96];
    std::snprintf(text, sizeof text, "%.2f ms (min %.2f, max %.2f)", v[v.size() / 2], v.front(), v.back());
    return text;
}

// Renders `frames` timed frames (after the caller's warm-up frame); returns the last frame's
// statistics with every time replaced by its median, and prints median, minimum and maximum.
FrameStats benchmark(Renderer& r, const Settings& s, int frames, const fs::path& preset) {
    std::vector<double> shadow, main, cpu, wall;
    FrameStats stats;
    for (int f = 0; f < frames; ++f) {
        auto t0 = std::chrono::steady_clock::now();
        stats = r.render(s);
        finishDeviceWork();
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        shadow.push_back(stats.gpuShadowMs);
        main.push_back(stats.gpuMainMs);
        cpu.push_back(stats.cpuMs);
    }
    std::printf("%s: %d frames at %dx%d, every map redrawn: frame %s, GPU shadow %s, GPU main %s, CPU submit %s\n",
                preset.string().c_str(), frames, s.output.width, s.output.height, spread(wall).c_str(),
                spread(shadow).c_str(), spread(main).c_str(), spread(cpu).c_str());
    stats.gpuShadowMs = median(shadow);
    stats.gpuMainMs = median(main);
    stats.cpuMs = median(cpu);
    return stats;
}

// The preset's timed frame(s), honest: a warm-up frame first, untimed, because Mesa compiles a
// shader variant at its first draw with a given state, inside whichever frame draws first (1.1 s
// of "main" for ogldev-49); then every map redrawn in each timed frame, since a map kept from the
// previous preset or frame costs nothing and would print as 0.0 ms.
FrameStats timedFrames(Renderer& r, const Settings& s, int frames, const fs::path& preset) {
    const st::RenderOptions options = r.options();
    st::RenderOptions redraw = options;
    redraw.cacheMaps = false;
    r.setOptions(redraw);
    r.render(s);
    FrameStats stats = frames > 1 ? benchmark(r, s, frames, preset) : r.render(s);
    r.setOptions(options);
    return stats;
}

// The GL work of one preset; the returned writer saves the image and statistics.
PresetWriter renderOne(const RenderOptions& opt, const metrics::CostProfile& profile, const fs::path& preset,
                       SceneCache<>& cache, MeasurePass& pass) {
    Settings s = loadPreset(preset);
    if (opt.view) s.output.view = *opt.view;
    if (opt.width) s.output.width = *opt.width;
    if (opt.height) s.output.height = *opt.height;
    checkDeviceLimits(s, preset);
    Renderer& r = cache.rendererFor(s, folderOf(preset));
    FrameStats stats = timedFrames(r, s, opt.frames, preset);
    const metrics::ModelledCost model = metrics::modelFrame(profile, stats.work);  // every map was redrawn
    stats.modelMs = model.totalMs;
    stats.modelShadowMs = model.shadowMs;
    stats.costProfile = metrics::profileName(profile);
    Rgba8Image img{r.width(), r.height(), r.readRgba8()};
    stats.warnings = metrics::frameWarnings(r, pass, s, stats, opt.warningLimits);
    for (const std::string& w : stats.warnings) std::fprintf(stderr, "%s: warning: %s\n", preset.string().c_str(), w.c_str());
    return [outDir = opt.outDir, preset, s, stats, model, img = std::move(img)] {
        const std::string stem = preset.stem().string();
        const fs::path png = outDir / (stem + ".png");
        writeImageAtomic(png, img);
        writeTextAtomic(outDir / (stem + ".json"), toJsonText(stats));
        // "4 x 1024² maps" when every cascade has one size, else each size; then the storage.
        std::string maps = std::to_string(s.cascades.count) + " x " + std::to_string(s.cascades.mapSize) + "²";
        if (!s.cascades.mapSizes.empty()) {
            maps.clear();
            for (int size : s.cascades.mapSizes) maps += (maps.empty() ? "" : "+") + std::to_string(size) + "²";
        }
        // One cost figure, labelled: the model with every pass it prices, and the GPU timers with every
        // pass they timed (issue 39 #4: the filter pass was in the model and missing from the timers).
        std::string timers = shadowTimeText(stats);
        char pass[64];
        if (stats.gpuFilterMs > 0.0) {
            std::snprintf(pass, sizeof pass, ", filter %.1f ms", stats.gpuFilterMs);
            timers += pass;
        }
        if (const double screen = stats.gpuScreenShadowMs + stats.gpuScreenBlurMs; screen > 0.0) {
            std::snprintf(pass, sizeof pass, ", screen mask %.1f ms", screen);
            timers += pass;
        }
        std::printf("wrote %s (%dx%d, view %s, %s maps (%s), modelled cost %.1f ms (shadow %.1f, filter %.1f, main %.1f); "
                    "GPU timers: %s, main %.1f ms)\n",
                    png.string().c_str(), img.width, img.height, enumName(s.output.view).c_str(), maps.c_str(),
                    enumName(s.cascades.storage).c_str(), stats.modelMs, stats.modelShadowMs, model.filterMs, model.mainMs,
                    timers.c_str(), stats.gpuMainMs);
        std::fflush(stdout);
    };
}

// A .gltf or .glb given to render becomes a preset of its own (app/scene_preset.h), written as
// OUT/presets/<stem>.json (OUT/<stem>.json holds the frame's statistics), so the picture can be
// replayed and edited.
std::vector<fs::path> presetsOf(const RenderOptions& opt) {
    std::vector<fs::path> presets;
    for (const fs::path& p : opt.presets) {
        if (!isGltfPath(p)) {
            presets.push_back(p);
            continue;
        }
        const fs::path dir = opt.outDir / "presets";
        makeOutputDir(dir);
        const fs::path preset = dir / (p.stem().string() + ".json");
        savePresetAtomic(presetForScene(p, dir), preset);
        std::printf("wrote %s for %s\n", preset.string().c_str(), p.string().c_str());
        presets.push_back(preset);
    }
    return presets;
}

}  // namespace

int runRender(const RenderOptions& given) {
    const auto profile = loadCostProfileOrReport(given.costProfile);
    if (!profile) return 1;
    RenderOptions opt = given;
    try {
        opt.presets = presetsOf(given);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return runHeadless({opt.presets, opt.outDir, opt.debugContext}, [&opt, profile]() -> PresetWork {
        auto cache = std::make_shared<SceneCache<>>();
        auto pass = std::make_shared<MeasurePass>();
        return [&opt, profile, cache, pass](const fs::path& preset) {
            return renderOne(opt, *profile, preset, *cache, *pass);
        };
    });
}

}  // namespace st::app
