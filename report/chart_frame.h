#pragma once
// The geometry every chart shares (report/ internals): page and plot rectangles in page pixels,
// value axes (linear or log, with their ticks) and the calls that put text and lines on them.
// Layout is computed in pixels, not PLplot's millimetres, so labels and the table can be placed
// around the data by arithmetic; font sizes scale with the page width (1200 px = 1).
#include <string>
#include <vector>

namespace st::report::detail {

struct Box {  // page pixels, y down
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
};
bool overlaps(const Box& a, const Box& b);
double overlapArea(const Box& a, const Box& b);

struct Tick {
    double world = 0;
    std::string label;  // PLplot text (may carry #u..#d)
};

struct Axis {
    double lo = 0, hi = 1;  // world bounds: the value, or log10 of it on a log axis
    bool log = false;
    double floor = 0;       // log axis: values <= 0 are drawn here
    int clamped = 0;        // log axis: how many values were <= 0
    std::vector<Tick> ticks;
    double majorStep = 0;   // linear axis: tick spacing for plbox; 1 on a category axis
    bool categorical = false;
    double world(double value) const;  // log10(max(value, floor)) on a log axis
};
// Bounds with padding and ticks for the finite values (a log axis also clamps values <= 0).
Axis valueAxis(const std::vector<double>& values, bool log);
Axis categoryAxis(const std::vector<std::string>& names);
std::string clampNote(const Axis& axis, const char* name);  // "" or "y <= 0 drawn at 0.001 (log axis)"

struct Frame {
    int width = 1200, height = 900;
    double scale = 1.0;      // width / 1200 (at least 0.75): every pixel size below is multiplied by it
    double pxPerMm = 1.0;    // read back from PLplot after plinit()
    Box plot;
    Axis x, y;
    double px(double size) const { return size * scale; }
    double pageX(double worldX) const;  // world -> page pixels
    double pageY(double worldY) const;
};
// Text and margins scale with the width, but not below 0.75 (16 px text stays 12 px on a small
// page).
Frame makeFrame(int width, int height);
void beginPage(Frame& frame);  // reads the page's pixels per millimetre

// Text sizes are the font size in pixels at scale 1.
void setTextPx(const Frame& frame, double px);
void usePageCoordinates(const Frame& frame);  // world = page pixels (y down is handled inside)
void usePlotCoordinates(const Frame& frame);  // viewport = plot box, world = axis bounds
// Text centred vertically on pageY; just 0 = left, 0.5 = centre, 1 = right.
void pageText(const Frame& frame, double pageX, double pageY, double just, const std::string& plplotText,
              double angleDeg = 0);

double textWidthPx(const std::string& plplotText, double fontPx);  // an estimate (DejaVu Sans)
double tickLabelWidthPx(const Axis& axis, double fontPx);

inline constexpr double kTickFont = 16, kAxisFont = 18, kTitleFont = 26, kSubtitleFont = 16;

// Plot rectangle for the axes: the left margin fits the y tick labels; `bottomPx` is where the
// x-axis title ends (page pixels).
void layoutPlot(Frame& frame, double topPx, double bottomPx);
void drawTitle(const Frame& frame, const std::string& title, const std::string& subtitle);
void drawAxes(const Frame& frame, const std::string& xLabel, const std::string& yLabel);

}  // namespace st::report::detail
