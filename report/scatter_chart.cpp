// writeScatterChart (report/charts.h): every point hollow, the front filled and joined in x
// order, reference presets as labelled diamonds, the legend in the emptiest corner and the front
// table under the plot.
#include "report/chart_frame.h"
#include "report/chart_marks.h"
#include "report/charts.h"
#include "report/front_table.h"
#include "report/palette.h"
#include "report/plot_output.h"

#include <plplot.h>

#include <algorithm>
#include <cmath>

namespace st::report {
namespace {
using namespace detail;

constexpr double kPlotTop = 92, kBaseHeight = 900, kFrontMarkerFont = 17, kReferenceFont = 19;

struct Drawn {  // the points with finite coordinates, in world units and page pixels
    std::vector<const ChartPoint*> points;
    std::vector<double> wx, wy;
    std::vector<PagePoint> page;
};

Drawn finitePoints(const Frame& f, const ScatterChart& chart) {
    Drawn d;
    for (const ChartPoint& p : chart.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        d.points.push_back(&p);
        d.wx.push_back(f.x.world(p.x)), d.wy.push_back(f.y.world(p.y));
        d.page.push_back({f.pageX(d.wx.back()), f.pageY(d.wy.back())});
    }
    return d;
}

std::string subtitle(const ScatterChart& chart, const Frame& f, std::size_t drawn) {
    std::string s = plText(chart.subtitle);
    auto add = [&s](const std::string& note) {
        if (!note.empty()) s += (s.empty() ? "" : "; ") + note;
    };
    add(clampNote(f.x, "x"));
    add(clampNote(f.y, "y"));
    std::size_t skipped = chart.points.size() - drawn;
    if (skipped) add(std::to_string(skipped) + (skipped == 1 ? " point" : " points") + " without a finite value not drawn");
    return s;
}

void drawFrontLine(const Drawn& d) {
    std::vector<std::pair<double, double>> front;
    for (std::size_t i = 0; i < d.points.size(); ++i)
        if (d.points[i]->onFront) front.emplace_back(d.wx[i], d.wy[i]);
    std::sort(front.begin(), front.end());
    std::vector<double> x, y;
    for (auto [px, py] : front) x.push_back(px), y.push_back(py);
    plcol0(kFront);
    plwidth(2.0);
    if (x.size() > 1) plline(PLINT(x.size()), x.data(), y.data());
}

// Hollow markers for the rest, then the front line and its filled markers, references on top.
void drawPoints(const Frame& f, const Drawn& d) {
    std::vector<double> x[3], y[3];  // rest, front, reference
    for (std::size_t i = 0; i < d.points.size(); ++i) {
        const ChartPoint& p = *d.points[i];
        for (int k : {p.onFront ? 1 : 0, p.reference ? 2 : -1})
            if (k >= 0) x[k].push_back(d.wx[i]), y[k].push_back(d.wy[i]);
    }
    usePlotCoordinates(f);
    drawMarkers(f, x[0], y[0], kHollowCircle, kAllPoints);
    drawFrontLine(d);
    drawMarkers(f, x[1], y[1], kFilledCircle, kFront, kFrontMarkerFont);
    drawMarkers(f, x[2], y[2], kDiamond, kReference, kReferenceFont);
}

std::vector<LegendEntry> legendEntries(const Drawn& d) {
    bool front = false, reference = false;
    for (const ChartPoint* p : d.points) front |= p->onFront, reference |= p->reference;
    std::vector<LegendEntry> entries{{"all points", kAllPoints, kHollowCircle, false}};
    if (front) entries.push_back({"Pareto front", kFront, kFilledCircle, true, kFrontMarkerFont});
    if (reference) entries.push_back({"reference presets", kReference, kDiamond, false, kReferenceFont});
    return entries;
}

void drawReferenceLabels(const Frame& f, const Drawn& d, const Box& legend) {
    std::vector<LabelRequest> labels;
    for (std::size_t i = 0; i < d.points.size(); ++i)
        if (d.points[i]->reference && !d.points[i]->label.empty()) labels.push_back({d.page[i], plText(d.points[i]->label)});
    drawLabels(f, labels, {legend}, d.page);
}

int pageHeight(const ScatterChart& chart, const Frame& f) {
    if (chart.height > 0) return chart.height;
    return int(std::lround(f.px(kBaseHeight) + frontTableHeightPx(f, chart.tableRows.size())));
}

void drawScatter(const ScatterChart& chart, Frame f) {
    beginPage(f);
    std::vector<double> xs, ys;
    for (const ChartPoint& p : chart.points) xs.push_back(p.x), ys.push_back(p.y);
    f.x = valueAxis(xs, chart.logX), f.y = valueAxis(ys, chart.logY);
    double tableTop = f.height - frontTableHeightPx(f, chart.tableRows.size());
    layoutPlot(f, f.px(kPlotTop), tableTop - f.px(10));
    Drawn d = finitePoints(f, chart);
    drawTitle(f, chart.title, subtitle(chart, f, d.points.size()));
    drawAxes(f, chart.xLabel, chart.yLabel);
    drawPoints(f, d);
    Box legend = drawLegend(f, legendEntries(d), d.page);
    drawReferenceLabels(f, d, legend);
    drawFrontTable(f, tableTop, chart.tableHeader, chart.tableRows);
}
}  // namespace

void writeScatterChart(const ScatterChart& chart, const std::filesystem::path& png, const std::filesystem::path& svg) {
    int width = chart.width > 0 ? chart.width : 1200;
    Frame f = makeFrame(width, 0);
    f.height = pageHeight(chart, f);
    for (auto [file, format] : {std::pair{png, Format::Png}, std::pair{svg, Format::Svg}})
        if (!file.empty()) renderPage(file, format, f.width, f.height, [&] { drawScatter(chart, f); });
}

}  // namespace st::report
