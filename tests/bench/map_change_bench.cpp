// map_change_bench PRESET [--size WxH] [--from N] [--to N] [--frames N]: what a map-size change costs
// in its first frame against the redraws after it (issue 39 #7: a 4096 map's confirmation said
// ~313 ms a redraw and the first frame took 3.3 s). The editor's per-frame work, headless: the
// renderer's frame, the side view and the shadow-map tiles, wall time with the GL work finished.
// Prints the first frame, the median redraw (every map redrawn), the first frame's extra, the same
// extra per texel of the new maps, and a D32F allocation and clear alone; asserts nothing (the
// constant in ui/map_cost.h came from its figures).
#include "renderer/context/egl_context.h"
#include "renderer/gpu/gl.h"
#include "renderer/render/offscreen_target.h"
#include "renderer/render/renderer.h"
#include "renderer/render/shadow_map_view.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings_json.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <vector>

using namespace st;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// One editor frame's GL work: the scene, the picture-in-picture and the tiles (viewport_renderer.cpp).
struct EditorFrame {
    double wallMs = 0.0;
    double shadowGpuMs = 0.0;  // the renderer's timers of the redrawn maps (what the estimate scales)
};

EditorFrame editorFrame(Renderer& r, const Settings& s, OffscreenTarget& pip, ShadowMapView& tiles) {
    glFinish();
    const auto t0 = Clock::now();
    const FrameStats stats = r.render(s, OrbitCamera{});
    r.renderSideView(s, OrbitCamera{}, pip);
    tiles.update(r.shadowMaps(), 256);
    glFinish();
    EditorFrame f{msSince(t0), 0.0};
    for (const CascadeStats& c : stats.cascades)
        if (c.redrawn) f.shadowGpuMs += c.gpuMs;
    return f;
}

// A D32F array of `layers` maps of side `size` allocated and cleared, as ShadowMaps::ensure and the
// first beginCascade do, timed alone.
double allocateAndClearMs(int size, int layers) {
    glFinish();
    const auto t0 = Clock::now();
    {
        gpu::Texture tex = gpu::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(tex.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
        const float one = 1.0f;
        glClearTexImage(tex.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
        glFinish();
    }
    glFinish();
    return msSince(t0);
}

}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    if (argc < 2) {
        std::fprintf(stderr, "usage: map_change_bench PRESET [--size WxH] [--from N] [--to N] [--frames N]\n");
        return 2;
    }
    try {
        const std::filesystem::path preset = argv[1];
        Settings s = loadPreset(preset);
        int from = s.cascades.mapSize, to = 4096, frames = 3;
        for (int i = 2; i + 1 < argc; i += 2) {
            if (!std::strcmp(argv[i], "--size")) std::sscanf(argv[i + 1], "%dx%d", &s.output.width, &s.output.height);
            else if (!std::strcmp(argv[i], "--from")) from = std::atoi(argv[i + 1]);
            else if (!std::strcmp(argv[i], "--to")) to = std::atoi(argv[i + 1]);
            else if (!std::strcmp(argv[i], "--frames")) frames = std::atoi(argv[i + 1]);
        }
        auto ctx = HeadlessContext::create(false);
        Scene scene = loadScene(s.scene, preset.parent_path(), {.ground = s.ground});
        Renderer r(scene);
        OffscreenTarget pip;
        pip.ensure(s.output.width / 4, s.output.height / 4);
        ShadowMapView tiles;

        s.cascades.mapSize = from;
        editorFrame(r, s, pip, tiles);  // shaders, scene upload
        r.invalidateMaps();
        const EditorFrame before = editorFrame(r, s, pip, tiles);  // what the estimate is scaled from

        s.cascades.mapSize = to;
        const EditorFrame first = editorFrame(r, s, pip, tiles);
        std::vector<double> redraws;
        for (int f = 0; f < frames; ++f) {
            r.invalidateMaps();  // a redraw: every map drawn again, as a sun or setting change does
            redraws.push_back(editorFrame(r, s, pip, tiles).wallMs);
        }
        const double redraw = medianOf(redraws);
        const double texels = double(s.cascades.count) * double(to) * double(to);
        const double estimate = before.shadowGpuMs / (double(s.cascades.count) * from * from) * texels;
        std::printf("%s %dx%d, %d cascades: %d -> %d maps\n", preset.filename().string().c_str(), s.output.width,
                    s.output.height, s.cascades.count, from, to);
        std::printf("  frame at %d (every map redrawn) %.0f ms, shadow timers %.0f ms -> editor's estimate at %d: %.0f ms\n",
                    from, before.wallMs, before.shadowGpuMs, to, estimate);
        std::printf("  first frame at %d %.0f ms, then a redraw %.0f ms (median of %d): extra %.0f ms = %.1f ns per texel\n",
                    to, first.wallMs, redraw, frames, first.wallMs - redraw, 1e6 * (first.wallMs - redraw) / texels);
        const double alloc = allocateAndClearMs(to, s.cascades.count);
        std::printf("  D32F %d x %d x %d allocated and cleared alone: %.0f ms = %.1f ns per texel\n", to, to,
                    s.cascades.count, alloc, 1e6 * alloc / texels);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "map_change_bench: %s\n", e.what());
        return 1;
    }
}
