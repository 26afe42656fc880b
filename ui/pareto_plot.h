#pragma once
// The Sweep panel's Pareto chart, drawn with ImGui's draw list: error against cost, every point,
// the front joined, the current settings and A marked, a legend; hover names a point, a click
// picks it. The mapping and picking are pure functions so they are tested without a frame.
#include "ui/compare_view.h"

#include <imgui.h>

#include <optional>
#include <vector>

namespace st::ui {

// Data ranges mapped onto a screen rectangle (y grows upwards in data, downwards on screen).
struct PlotMapping {
    ImVec2 min{0.0f, 0.0f}, max{1.0f, 1.0f};  // the plot area, screen pixels
    double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
    ImVec2 toScreen(double x, double y) const;
};

// "Nice" tick values (1, 2, 5 x 10^k steps) covering [lo, hi] with at most maxTicks inside.
std::vector<double> niceTicks(double lo, double hi, int maxTicks);

// Data range of `values` padded by 5 % each side, widened to niceTicks' outer ticks; a single
// value or none gets a unit-wide range around it.
std::pair<double, double> paddedRange(const std::vector<double>& values);

// The index of the point nearest `mouse` within `maxDistance` pixels, or -1.
int nearestPoint(const std::vector<ImVec2>& screen, ImVec2 mouse, float maxDistance);

struct PlotResult {
    int hovered = -1;  // index into the points
    int clicked = -1;
    std::vector<ImVec2> screen;  // where each point was drawn
};

// Draws the chart into the current window over `size` pixels (an InvisibleButton takes the
// input). byMemory: shadow-map memory on x instead of GPU time. The references labelled "current"
// and "A" get their own marks.
PlotResult drawParetoPlot(const SweepView& view, bool byMemory, ImVec2 size);

// A chart's figures were measured from `measuredFrom`'s camera, sun and scene: once the live view
// left them, they describe another frame (issue 21 #11). False when nothing was measured yet.
bool measuredElsewhere(const std::optional<Settings>& measuredFrom, const Settings& live);

}  // namespace st::ui
