#pragma once
// Read-only figures from the renderer's FrameStats, drawn next to the knobs that move them:
// split distances, per-cascade light boxes, texel size, caster cost, memory and timing plots.
#include "renderer/render/frame_stats.h"
#include "ui/history.h"

namespace st::ui {

void drawCascadeFigures(const FrameStats* stats);  // under the cascade knobs
void drawTimingPlots(const TimingHistory& timing, const FrameStats* stats);

// Adds this frame's timings to the plots (nothing for the GPU without stats).
void recordTimings(TimingHistory& timing, const FrameStats* stats, double cpuFrameMs);

}  // namespace st::ui
