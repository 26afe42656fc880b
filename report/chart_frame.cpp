#include "report/chart_frame.h"

#include "report/palette.h"
#include "report/plot_output.h"

#include <plplot.h>

#include <algorithm>
#include <cmath>

namespace st::report::detail {

bool overlaps(const Box& a, const Box& b) { return overlapArea(a, b) > 0; }

double overlapArea(const Box& a, const Box& b) {
    double w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
    return w > 0 && h > 0 ? w * h : 0.0;
}

double Frame::pageX(double worldX) const { return plot.x0 + (worldX - x.lo) / (x.hi - x.lo) * plot.width(); }
double Frame::pageY(double worldY) const { return plot.y1 - (worldY - y.lo) / (y.hi - y.lo) * plot.height(); }

Frame makeFrame(int width, int height) {
    Frame f;
    f.width = width, f.height = height, f.scale = std::max(0.75, width / 1200.0);
    return f;
}

void beginPage(Frame& frame) {
    PLFLT x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    plgspa(&x0, &x1, &y0, &y1);
    frame.pxPerMm = frame.width / (x1 - x0);
}

// PLplot's character height is the height of a capital; a font of F pixels has capitals of
// about 0.72 F (DejaVu Sans), so the sizes here read like CSS font sizes.
void setTextPx(const Frame& frame, double px) { plschr(frame.px(px) * 0.72 / frame.pxPerMm, 1.0); }

void usePageCoordinates(const Frame& frame) {
    plvpor(0.0, 1.0, 0.0, 1.0);
    plwind(0.0, frame.width, 0.0, frame.height);
}

void usePlotCoordinates(const Frame& frame) {
    const Box& p = frame.plot;
    plvpor(p.x0 / frame.width, p.x1 / frame.width, 1.0 - p.y1 / frame.height, 1.0 - p.y0 / frame.height);
    plwind(frame.x.lo, frame.x.hi, frame.y.lo, frame.y.hi);
}

void pageText(const Frame& frame, double pageX, double pageY, double just, const std::string& text, double angleDeg) {
    double a = angleDeg * M_PI / 180.0;
    plptex(pageX, frame.height - pageY, std::cos(a), std::sin(a), just, text.c_str());
}

// Code points outside escape sequences, at DejaVu Sans' mean advance of ~0.6 em.
double textWidthPx(const std::string& text, double fontPx) {
    double chars = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '#' && i + 1 < text.size() && text[i + 1] != '#') {
            ++i;  // "#u", "#d": no advance
            continue;
        }
        if (text[i] == '#') ++i;
        if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) chars += 1;
    }
    return chars * 0.6 * fontPx;
}

double tickLabelWidthPx(const Axis& axis, double fontPx) {
    double w = 0;
    for (const Tick& t : axis.ticks) w = std::max(w, textWidthPx(t.label, fontPx));
    return w;
}

void layoutPlot(Frame& frame, double topPx, double bottomPx) {
    double yTicks = tickLabelWidthPx(frame.y, frame.px(kTickFont));
    frame.plot.x0 = frame.px(24 + kAxisFont + 14 + 10) + yTicks;
    frame.plot.x1 = frame.width - frame.px(40);
    frame.plot.y0 = topPx;
    frame.plot.y1 = bottomPx - frame.px(66);
}

// A line centred on the page in at most `fontPx`, smaller when it would not fit between the
// page's margins (a tune's title names the scene, size, figure, cost and profile), down to a
// floor below which it stays legible and is clipped.
void centredLine(const Frame& frame, double yPx, double fontPx, const std::string& text) {
    const double room = frame.width - 2.0 * frame.px(12);
    const double wide = textWidthPx(text, frame.px(fontPx));
    const double fit = wide > room ? fontPx * room / wide : fontPx;
    setTextPx(frame, std::max(fit, std::min(fontPx, 11.0)));
    pageText(frame, frame.width / 2.0, frame.px(yPx), 0.5, text);
}

void drawTitle(const Frame& frame, const std::string& title, const std::string& subtitle) {
    usePageCoordinates(frame);
    plcol0(kInk);
    centredLine(frame, 34, kTitleFont, plText(title));
    plcol0(kMutedInk);
    centredLine(frame, 66, kSubtitleFont, subtitle);
}

namespace {
void gridLines(const Frame& frame) {
    plcol0(kGrid);
    plwidth(1.0);
    for (const Tick& t : frame.x.ticks) {
        PLFLT xs[2] = {t.world, t.world}, ys[2] = {frame.y.lo, frame.y.hi};
        if (!frame.x.categorical) plline(2, xs, ys);
    }
    for (const Tick& t : frame.y.ticks) {
        PLFLT xs[2] = {frame.x.lo, frame.x.hi}, ys[2] = {t.world, t.world};
        plline(2, xs, ys);
    }
}

void box(const Axis& x, const Axis& y) {
    auto opts = [](const Axis& a) { return a.categorical ? "bct" : a.log ? "bcstl" : "bcst"; };
    plcol0(kInk);
    plwidth(1.2);
    plbox(opts(x), x.log ? 0.0 : x.majorStep, x.categorical ? 1 : 0, opts(y), y.log ? 0.0 : y.majorStep, 0);
}

void tickLabels(const Frame& frame) {
    setTextPx(frame, kTickFont);
    for (const Tick& t : frame.x.ticks) pageText(frame, frame.pageX(t.world), frame.plot.y1 + frame.px(20), 0.5, t.label);
    for (const Tick& t : frame.y.ticks) pageText(frame, frame.plot.x0 - frame.px(8), frame.pageY(t.world), 1.0, t.label);
}
}  // namespace

void drawAxes(const Frame& frame, const std::string& xLabel, const std::string& yLabel) {
    usePlotCoordinates(frame);
    gridLines(frame);
    box(frame.x, frame.y);
    usePageCoordinates(frame);
    plcol0(kInk);
    tickLabels(frame);
    setTextPx(frame, kAxisFont);
    double yTicks = tickLabelWidthPx(frame.y, frame.px(kTickFont));
    pageText(frame, (frame.plot.x0 + frame.plot.x1) / 2, frame.plot.y1 + frame.px(50), 0.5, plText(xLabel));
    pageText(frame, frame.plot.x0 - frame.px(8 + 14) - yTicks - frame.px(kAxisFont / 2), (frame.plot.y0 + frame.plot.y1) / 2,
             0.5, plText(yLabel), 90);
}

}  // namespace st::report::detail
