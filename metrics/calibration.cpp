#include "metrics/calibration.h"

#include "metrics/cost.h"

#include <algorithm>
#include <stdexcept>

namespace st::metrics {

TimedFrames timeFrames(Renderer& r, const Settings& s, int frames) {
    if (frames < 1) throw std::invalid_argument("calibration: at least one timed frame");
    const RenderOptions options = r.options();
    RenderOptions redrawAll = options;
    redrawAll.cacheMaps = false;
    r.setOptions(redrawAll);
    TimedFrames t;
    try {
        r.render(s);  // untimed: compiles the program variants this preset uses
        for (int f = 0; f < frames; ++f) t.frames.push_back(r.render(s));
    } catch (...) {
        r.setOptions(options);
        throw;
    }
    r.setOptions(options);
    t.work = t.frames.front().work;
    for (const FrameStats& f : t.frames) t.workStable = t.workStable && f.work == t.work;
    return t;
}

double minimum(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

namespace {
template <class Get>
CalibrationSample sample(const std::string& preset, PassKind kind, std::string pass, const PassWork& work,
                         const TimedFrames& t, Get ms) {
    std::vector<double> times;
    for (const FrameStats& f : t.frames) times.push_back(ms(f));
    return {preset, kind, std::move(pass), work, minimum(times), median(times)};
}
}  // namespace

std::vector<CalibrationSample> passSamples(const std::string& preset, const TimedFrames& t) {
    std::vector<CalibrationSample> out;
    for (std::size_t i = 0; i < t.work.cascades.size(); ++i) {
        if (!didWork(t.work.cascades[i])) continue;
        out.push_back(sample(preset, PassKind::Cascade, "cascade " + std::to_string(i), t.work.cascades[i], t,
                             [i](const FrameStats& f) { return i < f.cascades.size() ? f.cascades[i].gpuMs : 0.0; }));
    }
    out.push_back(sample(preset, PassKind::Main, "main", t.work.main, t, [](const FrameStats& f) { return f.gpuMainMs; }));
    if (didWork(t.work.filter))
        out.push_back(sample(preset, PassKind::Filter, "filter", t.work.filter, t,
                             [](const FrameStats& f) { return f.gpuFilterMs; }));
    if (didWork(t.work.depthBounds))
        out.push_back(sample(preset, PassKind::DepthBounds, "depthBounds", t.work.depthBounds, t,
                             [](const FrameStats& f) { return f.gpuDepthBoundsMs; }));
    return out;
}

std::vector<double> frameTotalsMs(const TimedFrames& t) {
    std::vector<double> out;
    for (const FrameStats& f : t.frames) out.push_back(f.gpuShadowMs + f.gpuMainMs + f.gpuFilterMs + f.gpuDepthBoundsMs);
    return out;
}

}  // namespace st::metrics
