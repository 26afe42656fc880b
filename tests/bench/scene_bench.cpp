// scene_bench PRESET [--size WxH] [--map N] [--frames N]: the shadow pass of the clustered,
// culled, cached renderer against the naive one (issue 11) in one run, on one context. Prints
// medians and ratios; asserts nothing (scripts/bench_scene.sh runs it).
//   naive   every caster draw item in every cascade it touches, one draw each, every map every frame
//   culled  clusters culled by light box and swept footprint, batched; every map every frame
//   still   culled + cached maps, camera still
//   moving  culled + cached maps, camera moving 0.1 m per frame along its view
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

struct Figures {
    double shadowMs = 0, mainMs = 0, frameMs = 0;
    double triangles = 0, lowerBound = 0, draws = 0, mainTriangles = 0, redrawn = 0;
};

Figures run(Renderer& r, Settings s, RenderOptions o, int frames, bool moving) {
    r.setOptions(o);
    r.invalidateMaps();
    r.render(s);  // warm-up
    std::vector<double> shadow, main, frame, tris, bound, draws, mainTris, redrawn;
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
    }
    return {median(shadow), median(main), median(frame), median(tris), median(bound), median(draws), median(mainTris),
            median(redrawn)};
}

void print(const char* name, const Figures& f) {
    std::printf("  %-7s shadow %8.2f ms  main %7.2f ms  frame %8.2f ms  caster triangles %9.0f  draws %6.0f  "
                "maps redrawn %.0f  main triangles %9.0f\n",
                name, f.shadowMs, f.mainMs, f.frameMs, f.triangles, f.draws, f.redrawn, f.mainTriangles);
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: scene_bench PRESET [--size WxH] [--map N] [--frames N] [--naive-only-shadow]\n");
        return 2;
    }
    try {
        const std::filesystem::path preset = argv[1];
        Settings s = loadPreset(preset);
        int frames = 7;
        for (int i = 2; i + 1 < argc; i += 2) {
            if (!std::strcmp(argv[i], "--size")) std::sscanf(argv[i + 1], "%dx%d", &s.output.width, &s.output.height);
            else if (!std::strcmp(argv[i], "--map")) s.cascades.mapSize = std::atoi(argv[i + 1]);
            else if (!std::strcmp(argv[i], "--frames")) frames = std::atoi(argv[i + 1]);
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
        const Figures naive = run(r, s, {.naive = true}, frames, false);
        const Figures culled = run(r, s, {.cacheMaps = false}, frames, false);
        const Figures still = run(r, s, {}, frames, false);
        const Figures moving = run(r, s, {}, frames, true);
        print("naive", naive);
        print("culled", culled);
        print("still", still);
        print("moving", moving);
        auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
        std::printf("  shadow-pass GPU time vs naive: culled %.2fx, still %.2fx, moving %.2fx (target <= 0.5x)\n",
                    ratio(culled.shadowMs, naive.shadowMs), ratio(still.shadowMs, naive.shadowMs),
                    ratio(moving.shadowMs, naive.shadowMs));
        std::printf("  frame time vs naive: culled %.2fx, still %.2fx, moving %.2fx\n", ratio(culled.frameMs, naive.frameMs),
                    ratio(still.frameMs, naive.frameMs), ratio(moving.frameMs, naive.frameMs));
        std::printf("  caster triangles submitted / lower bound: culled %.0f / %.0f = %.2fx (target <= 1.1x); naive %.2fx\n",
                    culled.triangles, culled.lowerBound, ratio(culled.triangles, culled.lowerBound),
                    ratio(naive.triangles, culled.lowerBound));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scene_bench: %s\n", e.what());
        return 1;
    }
}
