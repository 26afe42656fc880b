// writeLineChart (report/charts.h): one line with markers per series, a legend in the emptiest
// corner, a category axis when xTickLabels is set.
#include "report/chart_frame.h"
#include "report/chart_marks.h"
#include "report/charts.h"
#include "report/palette.h"
#include "report/plot_output.h"

#include <plplot.h>

#include <cmath>

namespace st::report {
namespace {
using namespace detail;

constexpr double kPlotTop = 92, kSeriesMarkerFont = 17;

int seriesColour(std::size_t i) { return kSeries0 + int(i % kSeriesCount); }

// Runs of finite points are joined; a NaN breaks the line instead of bending it to zero.
void drawSeries(const Frame& f, const Series& s, std::size_t index, std::vector<PagePoint>& page) {
    std::vector<double> x, y, mx, my;
    auto flush = [&] {
        plcol0(seriesColour(index));
        plwidth(2.0);
        if (x.size() > 1) plline(PLINT(x.size()), x.data(), y.data());
        x.clear(), y.clear();
    };
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
            flush();
            continue;
        }
        x.push_back(f.x.world(s.x[i])), y.push_back(f.y.world(s.y[i]));
        mx.push_back(x.back()), my.push_back(y.back());
        page.push_back({f.pageX(x.back()), f.pageY(y.back())});
    }
    flush();
    drawMarkers(f, mx, my, seriesGlyph(index), seriesColour(index), kSeriesMarkerFont);
}

void drawLines(const LineChart& chart, Frame f) {
    beginPage(f);
    std::vector<double> xs, ys;
    for (const Series& s : chart.series) xs.insert(xs.end(), s.x.begin(), s.x.end()), ys.insert(ys.end(), s.y.begin(), s.y.end());
    f.x = chart.xTickLabels.empty() ? valueAxis(xs, false) : categoryAxis(chart.xTickLabels);
    f.y = valueAxis(ys, chart.logY);
    layoutPlot(f, f.px(kPlotTop), f.height - f.px(10));
    std::string sub = plText(chart.subtitle), note = clampNote(f.y, "y");
    drawTitle(f, chart.title, sub + (sub.empty() || note.empty() ? "" : "; ") + note);
    drawAxes(f, chart.xLabel, chart.yLabel);
    usePlotCoordinates(f);
    std::vector<PagePoint> page;
    std::vector<LegendEntry> legend;
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
        drawSeries(f, chart.series[i], i, page);
        legend.push_back({plText(chart.series[i].name), seriesColour(i), seriesGlyph(i), true, kSeriesMarkerFont});
    }
    if (!legend.empty()) drawLegend(f, legend, page);
}
}  // namespace

void writeLineChart(const LineChart& chart, const std::filesystem::path& png, const std::filesystem::path& svg) {
    int width = chart.width > 0 ? chart.width : 1200;
    Frame f = makeFrame(width, 0);
    f.height = chart.height > 0 ? chart.height : int(std::lround(f.px(900)));
    for (auto [file, format] : {std::pair{png, Format::Png}, std::pair{svg, Format::Svg}})
        if (!file.empty()) renderPage(file, format, f.width, f.height, [&] { drawLines(chart, f); });
}

}  // namespace st::report
