#include "metrics/cost.h"

#include <algorithm>
#include <stdexcept>

namespace st::metrics {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

namespace {
template <class Get>
double medianOf(const std::vector<FrameStats>& frames, Get get) {
    std::vector<double> values;
    for (const FrameStats& f : frames) values.push_back(get(f));
    return median(std::move(values));
}

template <class Get>
TimeRange rangeOf(const std::vector<FrameStats>& frames, Get get) {
    TimeRange r{get(frames.front()), get(frames.front())};
    for (const FrameStats& f : frames) {
        r.minMs = std::min(r.minMs, get(f));
        r.maxMs = std::max(r.maxMs, get(f));
    }
    return r;
}
}  // namespace

CostReport summariseCost(const std::vector<FrameStats>& frames, const std::vector<std::size_t>& covered, int mapSize) {
    if (frames.empty()) throw std::invalid_argument("cost: no timed frames");
    const FrameStats& last = frames.back();
    CostReport r;
    r.frames = int(frames.size());
    r.gpuShadowMs = medianOf(frames, [](const FrameStats& f) { return f.gpuShadowMs; });
    r.gpuMainMs = medianOf(frames, [](const FrameStats& f) { return f.gpuMainMs; });
    r.cpuMs = medianOf(frames, [](const FrameStats& f) { return f.cpuMs; });
    r.gpuFilterMs = medianOf(frames, [](const FrameStats& f) { return f.gpuFilterMs; });
    r.gpuShadowRange = rangeOf(frames, [](const FrameStats& f) { return f.gpuShadowMs; });
    r.gpuMainRange = rangeOf(frames, [](const FrameStats& f) { return f.gpuMainMs; });
    r.gpuFilterRange = rangeOf(frames, [](const FrameStats& f) { return f.gpuFilterMs; });
    r.cpuRange = rangeOf(frames, [](const FrameStats& f) { return f.cpuMs; });
    for (const FrameStats& f : frames)
        if (!(f.work == last.work)) throw std::logic_error("cost: the counted work differs between timed frames of the same settings");
    r.work = last.work;
    r.shadowMapBytes = last.shadowMapBytes;
    r.filterMapBytes = last.filterMapBytes;
    r.sceneTriangles = last.sceneTriangles;
    for (std::size_t i = 0; i < last.cascades.size(); ++i) {
        CascadeCost c;
        c.draws = last.cascades[i].casterDraws;
        c.triangles = last.cascades[i].casterTriangles;
        c.gpuMs = medianOf(frames, [i](const FrameStats& f) { return f.cascades[i].gpuMs; });
        const int side = last.cascades[i].mapSize > 0 ? last.cascades[i].mapSize : mapSize;  // its own size
        c.texels = std::size_t(side) * std::size_t(side);
        c.texelsCovered = i < covered.size() ? covered[i] : 0;
        r.draws += c.draws;
        r.triangles += c.triangles;
        r.texels += c.texels;
        r.texelsCovered += c.texelsCovered;
        r.cascades.push_back(c);
    }
    return r;
}

}  // namespace st::metrics
