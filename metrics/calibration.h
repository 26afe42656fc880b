#pragma once
// The timings `shadowtune calibrate` fits the cost model on (metrics/cost_model.h): one preset's
// passes timed over several frames with every map redrawn, after an untimed frame that compiles
// the programs it uses. Needs a current GL 4.5 context.
#include "metrics/cost_model.h"
#include "renderer/render/frame_stats.h"
#include "renderer/render/renderer.h"
#include "renderer/settings/settings.h"

#include <string>
#include <vector>

namespace st::metrics {

struct TimedFrames {
    std::vector<FrameStats> frames;  // the timed ones
    FrameWork work;                  // of the first timed frame
    bool workStable = true;          // every timed frame counted the same work
};

// One untimed frame (first-use compiles and allocations), then `frames` timed frames with
// RenderOptions::cacheMaps off so every cascade's map is drawn in each. The renderer's options
// are restored afterwards. Throws std::invalid_argument for frames < 1 or settings the cascade
// math rejects.
TimedFrames timeFrames(Renderer& r, const Settings& s, int frames);

// Per pass that did work: its counted work and its minimum and median time over the frames.
std::vector<CalibrationSample> passSamples(const std::string& preset, const TimedFrames& t);

// The frame's GPU time (every pass: cascades, main, filter, depth bounds) of each timed frame.
std::vector<double> frameTotalsMs(const TimedFrames& t);

double minimum(const std::vector<double>& v);  // 0 for none

}  // namespace st::metrics
