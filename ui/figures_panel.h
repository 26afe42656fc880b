#pragma once
// Read-only figures from the renderer's FrameStats, drawn next to the knobs that move them:
// split distances, per-cascade light boxes, texel size, caster cost, memory and timing plots.
#include "renderer/render/frame_stats.h"
#include "renderer/settings/settings.h"
#include "ui/advice.h"
#include "ui/history.h"
#include "ui/item_rects.h"

#include <string>
#include <vector>

namespace st::ui {

std::string drawCascadeFigures(const Settings& s, const FrameStats* stats, ItemRects& rects);  // under the cascade knobs, with advice
// Advice (ui/advice.h) as wrapped lines in the advice colour, recorded as "advice.<rule>".
// Each piece of advice with a "Tune for this" button: returns the rule whose button was pressed,
// or "".
std::string drawAdvice(const std::vector<Advice>& advice, ItemRects& rects);
void drawTimingPlots(const TimingHistory& timing, const FrameStats* stats);

// Adds this frame's timings to the plots (nothing for the GPU without stats).
void recordTimings(TimingHistory& timing, const FrameStats* stats, double cpuFrameMs);

}  // namespace st::ui
