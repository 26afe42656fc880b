#pragma once
// Charts of the sweep and the measurements (docs/architecture.md "Speed vs accuracy"), drawn with
// PLplot's cairo drivers into PNG and SVG. Plain data in, files out: no GL, no Settings.
// Every chart has a title, axis labels with units and a legend; files are written to a temporary
// name and renamed, so an interrupted run leaves no half-written chart.
#include <filesystem>
#include <string>
#include <vector>

namespace st::report {

struct ChartPoint {
    double x = 0.0;
    double y = 0.0;
    std::string label;       // shown next to reference points and in the front table
    bool onFront = false;    // joined by the front line, drawn filled
    bool reference = false;  // a labelled reference preset (drawn as a distinct marker)
};

// Error against cost: every point, the Pareto front joined in x order, reference presets
// labelled, and the front's points listed in a table below the plot.
struct ScatterChart {
    std::string title;     // e.g. "truck_town 640x360: misclassified vs GPU time"
    std::string subtitle;  // e.g. the machine and the date
    std::string xLabel;    // with unit: "GPU time, shadow + main (ms)"
    std::string yLabel;    // with unit: "misclassified (% of sun-facing pixels)"
    bool logX = false;
    bool logY = false;
    std::vector<ChartPoint> points;
    std::vector<std::string> tableHeader;             // columns of the front table
    std::vector<std::vector<std::string>> tableRows;  // one row per front point
    // Page size in pixels (SVG: the same in user units); 0 = the default, 1200 wide and 900 high,
    // taller by the front table. Text and margins scale with the width.
    int width = 0;
    int height = 0;
};

struct Series {
    std::string name;  // legend entry
    std::vector<double> x;
    std::vector<double> y;
};

// One or more figures against one axis. With xTickLabels the x values are indices into it
// (an enum axis such as fit: "cascade", "scene", "sphere").
struct LineChart {
    std::string title;
    std::string subtitle;
    std::string xLabel;
    std::string yLabel;
    bool logY = false;
    std::vector<std::string> xTickLabels;
    std::vector<Series> series;
    int width = 0;   // as ScatterChart: 0 = 1200
    int height = 0;  // 0 = 900
};

// Throw std::runtime_error naming the file on failure; `png` and `svg` may be empty to skip one.
void writeScatterChart(const ScatterChart& chart, const std::filesystem::path& png, const std::filesystem::path& svg);
void writeLineChart(const LineChart& chart, const std::filesystem::path& png, const std::filesystem::path& svg);

}  // namespace st::report
