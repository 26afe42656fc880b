#include "report/chart_marks.h"

#include "report/palette.h"

#include <plplot.h>

#include <algorithm>
#include <array>
#include <limits>

namespace st::report::detail {
namespace {

constexpr double kLegendFont = 16, kLabelFont = 15;

int markersIn(const Box& box, const std::vector<PagePoint>& markers, double radius) {
    int n = 0;
    for (const PagePoint& m : markers)
        n += m.x > box.x0 - radius && m.x < box.x1 + radius && m.y > box.y0 - radius && m.y < box.y1 + radius;
    return n;
}

struct Corner {
    PLINT position;
    bool right, top;
};
constexpr std::array<Corner, 4> kCorners{{{PL_POSITION_TOP | PL_POSITION_RIGHT, true, true},
                                          {PL_POSITION_TOP | PL_POSITION_LEFT, false, true},
                                          {PL_POSITION_BOTTOM | PL_POSITION_RIGHT, true, false},
                                          {PL_POSITION_BOTTOM | PL_POSITION_LEFT, false, false}}};
constexpr double kLegendInset = 0.015;  // of the plot's width and height

Box cornerBox(const Frame& f, const Corner& c, double w, double h) {
    double dx = kLegendInset * f.plot.width(), dy = kLegendInset * f.plot.height();
    double x0 = c.right ? f.plot.x1 - dx - w : f.plot.x0 + dx, y0 = c.top ? f.plot.y0 + dy : f.plot.y1 - dy - h;
    return {x0, y0, x0 + w, y0 + h};
}

// Ties go to the first corner of kCorners: top right, where an error-vs-cost chart is emptiest.
const Corner& quietestCorner(const Frame& f, double w, double h, const std::vector<PagePoint>& markers) {
    const Corner* best = &kCorners[0];
    int fewest = std::numeric_limits<int>::max();
    for (const Corner& c : kCorners) {
        int n = markersIn(cornerBox(f, c, w, h), markers, f.px(6));
        if (n < fewest) fewest = n, best = &c;
    }
    return *best;
}
}  // namespace

const char* seriesGlyph(std::size_t index) {
    static constexpr std::array<const char*, 5> glyphs{"●", "■", "▲", "◆", "▼"};
    return glyphs[index % glyphs.size()];
}

void drawMarkers(const Frame& frame, const std::vector<double>& x, const std::vector<double>& y, const char* glyph,
                 int colour, double fontPx) {
    if (x.empty()) return;
    plcol0(colour);
    setTextPx(frame, fontPx);
    plstring(PLINT(x.size()), x.data(), y.data(), glyph);
}

Box drawLegend(const Frame& f, const std::vector<LegendEntry>& entries, const std::vector<PagePoint>& markers) {
    std::size_t n = entries.size();
    double textW = 0;
    for (const LegendEntry& e : entries) textW = std::max(textW, textWidthPx(e.text, f.px(kLegendFont)));
    double estW = textW + f.px(90), estH = f.px(kLegendFont) * (1.9 * double(n) + 0.6);
    const Corner& corner = quietestCorner(f, estW, estH, markers);

    std::vector<const char*> text, glyphs;
    std::vector<PLINT> opts, colours, styles(n, 1), numbers, inks(n, kInk);
    std::vector<PLFLT> widths(n, 2.0), scales;
    for (const LegendEntry& e : entries) {
        text.push_back(e.text.c_str()), glyphs.push_back(e.glyph), colours.push_back(e.colour);
        opts.push_back(PL_LEGEND_SYMBOL | (e.line ? PL_LEGEND_LINE : 0));
        numbers.push_back(e.line ? 2 : 1);
        scales.push_back(e.glyphPx / kLegendFont);  // symbol sizes are relative to the legend's text
    }
    usePlotCoordinates(f);
    setTextPx(f, kLegendFont);
    PLFLT w = 0, h = 0;
    pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, PL_POSITION_VIEWPORT | PL_POSITION_INSIDE | corner.position,
             kLegendInset, kLegendInset, f.px(40) / f.plot.width(), kBackground, kMutedInk, 1, 0, 0, PLINT(n), opts.data(),
             1.0, 1.0, 1.9, 0.0, inks.data(), text.data(), nullptr, nullptr, nullptr, nullptr, colours.data(),
             styles.data(), widths.data(), colours.data(), scales.data(), numbers.data(), glyphs.data());
    return cornerBox(f, corner, w * f.plot.width(), h * f.plot.height());
}

namespace {
struct Spot {
    double dx, dy, just;  // direction from the anchor (in gaps), text justification
};
constexpr std::array<Spot, 8> kSpots{{{1, 0, 0}, {-1, 0, 1}, {0, -1, 0.5}, {0, 1, 0.5},
                                      {0.8, -0.8, 0}, {0.8, 0.8, 0}, {-0.8, -0.8, 1}, {-0.8, 0.8, 1}}};

Box spotBox(const LabelRequest& r, const Spot& s, double gap, double w, double h) {
    double cx = r.anchor.x + s.dx * gap, cy = r.anchor.y + s.dy * (gap + h / 2);
    double x0 = cx - s.just * w;
    return {x0, cy - h / 2, x0 + w, cy + h / 2};
}

double spotCost(const Frame& f, const Box& b, const std::vector<Box>& taken, const std::vector<PagePoint>& markers) {
    if (b.x0 < f.plot.x0 || b.x1 > f.plot.x1 || b.y0 < f.plot.y0 || b.y1 > f.plot.y1) return 1e9;
    double cost = 0;
    for (const Box& t : taken) cost += 100.0 * overlapArea(b, t) / (b.width() * b.height());
    return cost + 10.0 * markersIn(b, markers, f.px(5));
}
}  // namespace

void drawLabels(const Frame& f, const std::vector<LabelRequest>& labels, std::vector<Box> obstacles,
                const std::vector<PagePoint>& markers) {
    usePageCoordinates(f);
    plcol0(kInk);
    setTextPx(f, kLabelFont);
    double gap = f.px(11), h = f.px(kLabelFont) * 1.3;
    for (const LabelRequest& r : labels) {
        double w = textWidthPx(r.text, f.px(kLabelFont));
        Box best;
        const Spot* bestSpot = nullptr;
        double bestCost = std::numeric_limits<double>::infinity();
        for (const Spot& s : kSpots) {
            Box b = spotBox(r, s, gap, w, h);
            double cost = spotCost(f, b, obstacles, markers) + 0.5 * double(&s - kSpots.data());
            if (cost < bestCost) bestCost = cost, best = b, bestSpot = &s;
        }
        pageText(f, best.x0 + bestSpot->just * w, (best.y0 + best.y1) / 2, bestSpot->just, r.text);
        obstacles.push_back(best);
    }
}

}  // namespace st::report::detail
