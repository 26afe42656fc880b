#pragma once
// The editor's frame times, printed when it closes (the benchmarks read them): the wall and
// process CPU time of every frame, and the scene renders' times and scales.
#include <cstddef>
#include <utility>
#include <vector>

namespace st::app {

class FrameTimes {
public:
    void frame(double wallMs, double cpuMs) { frameMs_.push_back(wallMs), frameCpuMs_.push_back(cpuMs); }
    void sceneRender(double ms, double scale) { sceneMs_.push_back(ms), sceneScales_.push_back(scale); }
    void sceneReused() { ++reused_; }
    int frames() const { return int(frameMs_.size()); }
    // The last `n` scene renders, oldest first: wall ms and scale (the status file's "renders":
    // what a change's first frames cost, issue 39 #7).
    std::vector<std::pair<double, double>> lastRenders(std::size_t n) const {
        std::vector<std::pair<double, double>> out;
        for (std::size_t i = sceneMs_.size() > n ? sceneMs_.size() - n : 0; i < sceneMs_.size(); ++i)
            out.emplace_back(sceneMs_[i], sceneScales_[i]);
        return out;
    }
    // Medians of the frames after the first (it compiles shaders) and of the scene renders.
    void print() const;

private:
    std::vector<double> frameMs_;     // wall time of every frame
    std::vector<double> frameCpuMs_;  // CPU time of the whole process in every frame
    std::vector<double> sceneMs_;     // of every frame that rendered the scene
    std::vector<double> sceneScales_;
    int reused_ = 0;
};

// CPU time of every thread of the process (the UI, llvmpipe's rasterisers, the Accuracy rays):
// unlike wall time it barely depends on what else the machine runs, so a benchmark on a shared
// machine still says what a frame costs.
double processCpuMs();

}  // namespace st::app
