// scene_bench PRESET [--size WxH] [--map N] [--frames N]: the shadow pass of the clustered,
// culled, cached renderer against the naive one (issue 11) in one run, on one context. Prints
// medians and ratios; asserts nothing (scripts/bench_scene.sh runs it).
//   naive   every caster draw item in every cascade it touches, one draw each, every map every frame
//   culled  clusters culled by light box and swept footprint, batched; every map every frame
//   still   culled + cached maps, camera still
//   moving  culled + cached maps, camera moving 0.1 m per frame along its view
// Under each row, the main pass alone (wall time between glFinish calls: llvmpipe's timestamps
// bracket only part of a pass) and its counted work; --no-cached-rows runs naive and culled only.
#include "metrics/cost_model.h"
#include "metrics/cost_profile_json.h"
#include "renderer/context/egl_context.h"
#include "renderer/gpu/gl.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings_json.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

using namespace st;

namespace {
double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// The main pass's counted work, from pipeline statistics queries around one more main pass
// (renderMainView: the same plan and maps as the last frame). Identical in every run.
struct MainWork {
    std::uint64_t vertices = 0, primitives = 0, clipped = 0, fragments = 0, samplesPassed = 0;
    double wallMs = 0;  // median wall time of the pass alone, glFinish before and after
};

// The main pass's counts come from the renderer's own counters (FrameStats::work.main; its
// queries would clash with a second set opened around it). samplesPassed counts what passed the
// depth test when drawn, so it shows draw order, where llvmpipe's fragment-shader invocations
// count coverage before the depth test.
MainWork mainWork(Renderer& r, const Settings& s, OffscreenTarget& target, const PassWork& main) {
    const MainWork counts{main.vertices, main.primitives, main.clippedPrimitives, main.fragments, main.samplesPassed, 0.0};
    std::vector<double> wall;
    for (int i = 0; i < 3; ++i) {
        glFinish();
        const auto t0 = std::chrono::steady_clock::now();
        r.renderMainView(s, target);
        glFinish();
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    MainWork out = counts;
    out.wallMs = median(wall);
    return out;
}

struct Figures {
    double shadowMs = 0, mainMs = 0, frameMs = 0;
    double triangles = 0, lowerBound = 0, draws = 0, mainTriangles = 0, redrawn = 0, mainDraws = 0, mainRanges = 0;
    MainWork main;
    double modelMs = 0;  // the shipped cost model's ms for the frames' counted work (median)
};

// The shipped llvmpipe profile (presets/cost-profiles/llvmpipe.json): the modelled cost beside
// the timers, which on a CPU move with the load.
const metrics::CostProfile& profile() {
    static const metrics::CostProfile p =
        metrics::loadCostProfile(std::filesystem::path(ST_SOURCE_DIR) / "presets/cost-profiles/llvmpipe.json");
    return p;
}

Figures run(Renderer& r, Settings s, RenderOptions o, int frames, bool moving, OffscreenTarget& target) {
    r.setOptions(o);
    r.invalidateMaps();
    r.render(s);  // warm-up
    std::vector<double> shadow, main, frame, tris, bound, draws, mainTris, redrawn, mainDraws, mainRanges, model;
    PassWork mainCounts;  // the same in every frame
    const glm::vec3 step = 0.1f * glm::normalize(s.camera.target - s.camera.position);
    for (int f = 0; f < frames; ++f) {
        if (moving) s.camera.position += step, s.camera.target += step;
        const auto t0 = std::chrono::steady_clock::now();
        FrameStats st = r.render(s);
        glFinish();
        frame.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        shadow.push_back(st.gpuShadowMs);
        main.push_back(st.gpuMainMs);
        double t = 0, b = 0, d = 0, n = 0;
        for (const CascadeStats& c : st.cascades) {
            // Submitted this frame: a kept map submitted nothing.
            if (c.redrawn) t += double(c.casterTriangles), d += c.casterDraws, ++n;
            b += double(c.lowerBoundTriangles);
        }
        tris.push_back(t), bound.push_back(b), draws.push_back(d), redrawn.push_back(n);
        mainTris.push_back(double(st.mainTriangles));
        mainDraws.push_back(double(st.mainDraws));
        mainRanges.push_back(double(st.mainRanges));
        model.push_back(metrics::modelFrame(profile(), st.work).totalMs);
        mainCounts = st.work.main;
    }
    Figures f{median(shadow), median(main), median(frame), median(tris), median(bound), median(draws), median(mainTris),
              median(redrawn), median(mainDraws), median(mainRanges), {}};
    f.main = mainWork(r, s, target, mainCounts);
    f.modelMs = median(model);
    return f;
}

void print(const char* name, const Figures& f) {
    std::printf("  %-7s shadow %8.2f ms  main %7.2f ms  frame %8.2f ms  caster triangles %9.0f  draws %6.0f  "
                "maps redrawn %.0f  main triangles %9.0f  modelled frame %8.2f ms\n",
                name, f.shadowMs, f.mainMs, f.frameMs, f.triangles, f.draws, f.redrawn, f.mainTriangles, f.modelMs);
    std::printf("          main pass alone %.2f ms (wall)  work: draws %.0f (commands %.0f)  vertices %llu  primitives %llu  "
                "clipped %llu  fragments %llu  passed depth %llu\n",
                f.main.wallMs, f.mainDraws, f.mainRanges, (unsigned long long)f.main.vertices,
                (unsigned long long)f.main.primitives, (unsigned long long)f.main.clipped,
                (unsigned long long)f.main.fragments, (unsigned long long)f.main.samplesPassed);
}
}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows as they finish: the large scenes take minutes
    if (argc < 2) {
        std::fprintf(stderr, "usage: scene_bench PRESET [--size WxH] [--map N] [--frames N] [--no-cached-rows]\n");
        return 2;
    }
    try {
        const std::filesystem::path preset = argv[1];
        Settings s = loadPreset(preset);
        int frames = 7;
        bool cachedRows = true;
        for (int i = 2; i < argc; ++i) {
            const bool value = i + 1 < argc;
            if (!std::strcmp(argv[i], "--no-cached-rows")) cachedRows = false;
            else if (value && !std::strcmp(argv[i], "--size"))
                std::sscanf(argv[++i], "%dx%d", &s.output.width, &s.output.height);
            else if (value && !std::strcmp(argv[i], "--map")) s.cascades.mapSize = std::atoi(argv[++i]);
            else if (value && !std::strcmp(argv[i], "--frames")) frames = std::atoi(argv[++i]);
        }
        auto ctx = HeadlessContext::create(false);
        const auto l0 = std::chrono::steady_clock::now();
        Scene scene = loadScene(s.scene, preset.parent_path(), {.ground = s.ground});
        Renderer r(scene);
        const double loadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - l0).count();
        std::printf("%s: %zu triangles in %zu draw items, %zu clusters (load + upload %.0f ms); %dx%d, %d x %d maps, "
                    "%d frames per row (medians)\n",
                    preset.filename().string().c_str(), scene.triangleCount(), scene.draws.size(),
                    r.sceneGpu().clustered().clusters.size(), loadMs, s.output.width, s.output.height,
                    s.cascades.count, s.cascades.mapSize, frames);
        OffscreenTarget target;
        target.ensure(s.output.width, s.output.height);
        const Figures naive = run(r, s, {.naive = true}, frames, false, target);
        const Figures culled = run(r, s, {.cacheMaps = false}, frames, false, target);
        print("naive", naive);
        print("culled", culled);
        auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
        std::printf("  main pass alone vs naive: culled %.2fx wall, %.2fx fragments passing depth (shaded), %.2fx commands\n",
                    ratio(culled.main.wallMs, naive.main.wallMs),
                    ratio(double(culled.main.samplesPassed), double(naive.main.samplesPassed)),
                    ratio(culled.mainRanges, naive.mainRanges));
        std::printf("  caster triangles submitted / lower bound: culled %.0f / %.0f = %.2fx (target <= 1.1x); naive %.2fx\n",
                    culled.triangles, culled.lowerBound, ratio(culled.triangles, culled.lowerBound),
                    ratio(naive.triangles, culled.lowerBound));
        if (!cachedRows) {
            std::printf("  shadow-pass GPU time vs naive: culled %.2fx; frame time vs naive: culled %.2fx\n",
                        ratio(culled.shadowMs, naive.shadowMs), ratio(culled.frameMs, naive.frameMs));
            return 0;
        }
        const Figures still = run(r, s, {}, frames, false, target);
        const Figures moving = run(r, s, {}, frames, true, target);
        print("still", still);
        print("moving", moving);
        std::printf("  shadow-pass GPU time vs naive: culled %.2fx, still %.2fx, moving %.2fx (target <= 0.5x)\n",
                    ratio(culled.shadowMs, naive.shadowMs), ratio(still.shadowMs, naive.shadowMs),
                    ratio(moving.shadowMs, naive.shadowMs));
        std::printf("  frame time vs naive: culled %.2fx, still %.2fx, moving %.2fx\n", ratio(culled.frameMs, naive.frameMs),
                    ratio(still.frameMs, naive.frameMs), ratio(moving.frameMs, naive.frameMs));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scene_bench: %s\n", e.what());
        return 1;
    }
}
