#include "ui/pareto_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>

namespace st::ui {
namespace {

const ImU32 kGrid = IM_COL32(255, 255, 255, 40);
const ImU32 kAxis = IM_COL32(200, 200, 200, 255);
const ImU32 kPoint = IM_COL32(170, 170, 170, 255);
const ImU32 kFront = IM_COL32(255, 150, 30, 255);
const ImU32 kCurrent = IM_COL32(80, 220, 90, 255);
const ImU32 kA = IM_COL32(80, 200, 255, 255);
const ImU32 kHover = IM_COL32(255, 255, 255, 255);

std::string tickText(double v, double step) {
    char text[32];
    const int decimals = std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 6);
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

void diamond(ImDrawList* dl, ImVec2 c, float r, ImU32 col) {
    dl->AddQuadFilled({c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}, col);
}

void square(ImDrawList* dl, ImVec2 c, float r, ImU32 col) {
    dl->AddRectFilled({c.x - r, c.y - r}, {c.x + r, c.y + r}, col);
}

// One legend row: a mark, then its text; returns the x after it.
float legendEntry(ImDrawList* dl, ImVec2 at, int kind, ImU32 col, const char* text) {
    const ImVec2 c{at.x + 6.0f, at.y + ImGui::GetTextLineHeight() * 0.5f};
    if (kind == 0) dl->AddCircleFilled(c, 3.0f, col);
    if (kind == 1) dl->AddLine({c.x - 6.0f, c.y}, {c.x + 6.0f, c.y}, col, 2.0f), dl->AddCircleFilled(c, 3.5f, col);
    if (kind == 2) diamond(dl, c, 5.5f, col);
    if (kind == 3) square(dl, c, 4.5f, col);
    dl->AddText({at.x + 16.0f, at.y}, kAxis, text);
    return at.x + 22.0f + ImGui::CalcTextSize(text).x;
}

void drawAxes(ImDrawList* dl, const PlotMapping& m, const char* xLabel, const char* yLabel) {
    const float line = ImGui::GetTextLineHeight();
    const std::vector<double> xt = niceTicks(m.x0, m.x1, 6), yt = niceTicks(m.y0, m.y1, 5);
    const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1.0, ys = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
    for (const double x : xt) {
        const ImVec2 p = m.toScreen(x, m.y0);
        dl->AddLine({p.x, m.min.y}, {p.x, m.max.y}, kGrid);
        dl->AddLine({p.x, m.max.y}, {p.x, m.max.y + 4.0f}, kAxis);
        const std::string t = tickText(x, xs);
        dl->AddText({p.x - ImGui::CalcTextSize(t.c_str()).x * 0.5f, m.max.y + 5.0f}, kAxis, t.c_str());
    }
    for (const double y : yt) {
        const ImVec2 p = m.toScreen(m.x0, y);
        dl->AddLine({m.min.x, p.y}, {m.max.x, p.y}, kGrid);
        dl->AddLine({m.min.x - 4.0f, p.y}, {m.min.x, p.y}, kAxis);
        const std::string t = tickText(y, ys);
        dl->AddText({m.min.x - 6.0f - ImGui::CalcTextSize(t.c_str()).x, p.y - line * 0.5f}, kAxis, t.c_str());
    }
    dl->AddRect(m.min, m.max, kAxis);
    dl->AddText({(m.min.x + m.max.x - ImGui::CalcTextSize(xLabel).x) * 0.5f, m.max.y + 5.0f + line}, kAxis, xLabel);
    dl->AddText({m.min.x - 52.0f, m.min.y - line - 3.0f}, kAxis, yLabel);
}

}  // namespace

ImVec2 PlotMapping::toScreen(double x, double y) const {
    const double fx = x1 > x0 ? (x - x0) / (x1 - x0) : 0.5, fy = y1 > y0 ? (y - y0) / (y1 - y0) : 0.5;
    return {float(min.x + fx * (max.x - min.x)), float(max.y - fy * (max.y - min.y))};
}

std::vector<double> niceTicks(double lo, double hi, int maxTicks) {
    if (!(hi > lo) || maxTicks < 1 || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
    const double raw = (hi - lo) / maxTicks;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag * 10.0;
    for (const double k : {1.0, 2.0, 5.0, 10.0})
        if (k * mag >= raw) {
            step = k * mag;
            break;
        }
    std::vector<double> ticks;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step)
        ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
    return ticks;
}

std::pair<double, double> paddedRange(const std::vector<double>& values) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double v : values)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (!std::isfinite(lo)) return {0.0, 1.0};
    if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) return {lo - 0.5, hi + 0.5};
    const double pad = 0.05 * (hi - lo);
    return {lo - pad, hi + pad};
}

int nearestPoint(const std::vector<ImVec2>& screen, ImVec2 mouse, float maxDistance) {
    int best = -1;
    float bestD2 = maxDistance * maxDistance;
    for (std::size_t i = 0; i < screen.size(); ++i) {
        const float dx = screen[i].x - mouse.x, dy = screen[i].y - mouse.y;
        const float d2 = dx * dx + dy * dy;
        if (d2 <= bestD2) best = int(i), bestD2 = d2;
    }
    return best;
}

PlotResult drawParetoPlot(const SweepView& view, bool byMemory, ImVec2 size) {
    PlotResult result;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("paretoPlot", size);
    const bool hovered = ImGui::IsItemHovered();
    const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float line = ImGui::GetTextLineHeight();
    PlotMapping m;
    m.min = {origin.x + 58.0f, origin.y + line * 3.0f + 10.0f};  // title, legend, y label above
    m.max = {origin.x + size.x - 12.0f, origin.y + size.y - line * 2.0f - 10.0f};
    if (m.max.x - m.min.x < 40.0f || m.max.y - m.min.y < 40.0f) return result;

    auto xOf = [byMemory](const SweepPoint& p) { return byMemory ? p.memory : p.cost; };
    auto onFront = [byMemory](const SweepPoint& p) { return byMemory ? p.frontByMemory : p.frontByTime; };
    std::vector<double> xs, ys;
    for (const SweepPoint& p : view.points) xs.push_back(xOf(p)), ys.push_back(p.error);
    std::tie(m.x0, m.x1) = paddedRange(xs);
    std::tie(m.y0, m.y1) = paddedRange(ys);
    m.y0 = std::max(m.y0, std::min(0.0, m.y1 - 1.0));  // an error is never below 0
    drawAxes(dl, m, (byMemory ? view.memoryTitle : view.costTitle).c_str(), view.errorTitle.c_str());

    float lx = m.min.x;
    const ImVec2 legendAt{m.min.x, origin.y + line + 2.0f};
    lx = legendEntry(dl, {lx, legendAt.y}, 0, kPoint, "point");
    lx = legendEntry(dl, {lx, legendAt.y}, 1, kFront, "Pareto front");
    lx = legendEntry(dl, {lx, legendAt.y}, 2, kCurrent, "current");
    legendEntry(dl, {lx, legendAt.y}, 3, kA, "A");

    std::vector<ImVec2> screen;
    for (const SweepPoint& p : view.points) screen.push_back(m.toScreen(xOf(p), p.error));
    std::vector<int> front;
    for (std::size_t i = 0; i < view.points.size(); ++i)
        if (onFront(view.points[i])) front.push_back(int(i));
    std::sort(front.begin(), front.end(), [&](int a, int b) { return screen[a].x < screen[b].x; });
    dl->PushClipRect(m.min, m.max, true);
    for (std::size_t i = 1; i < front.size(); ++i) dl->AddLine(screen[front[i - 1]], screen[front[i]], kFront, 2.0f);
    for (std::size_t i = 0; i < view.points.size(); ++i) {
        const SweepPoint& p = view.points[i];
        if (p.reference && p.label == "current") diamond(dl, screen[i], 6.0f, kCurrent);
        else if (p.reference && p.label == "A") square(dl, screen[i], 5.0f, kA);
        else dl->AddCircleFilled(screen[i], onFront(p) ? 3.5f : 2.5f, onFront(p) ? kFront : kPoint);
    }
    if (hovered) result.hovered = nearestPoint(screen, ImGui::GetIO().MousePos, 10.0f);
    if (result.hovered >= 0) dl->AddCircle(screen[std::size_t(result.hovered)], 7.0f, kHover, 0, 1.5f);
    dl->PopClipRect();
    if (clicked) result.clicked = result.hovered;
    result.screen = std::move(screen);
    char title[160];
    std::snprintf(title, sizeof title, "%s, %dx%d: %zu of %zu points", view.scene.c_str(), view.width, view.height,
                  view.points.size(), view.total);
    dl->AddText({m.min.x, origin.y}, kAxis, title);
    return result;
}

bool measuredElsewhere(const std::optional<Settings>& measuredFrom, const Settings& live) {
    if (!measuredFrom) return false;
    const Settings& from = *measuredFrom;
    return from.camera != live.camera || from.light != live.light || from.scene != live.scene || from.ground != live.ground;
}

}  // namespace st::ui
