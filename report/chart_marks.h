#pragma once
// Marks on the plot (report/ internals): glyph markers, the legend in the emptiest corner, and
// point labels placed where they cover the fewest other labels and markers.
#include "report/chart_frame.h"

#include <string>
#include <utility>
#include <vector>

namespace st::report::detail {

struct PagePoint { double x = 0, y = 0; };  // page pixels

// Markers are text glyphs (PLplot's plstring) so the legend, which draws its symbols the same
// way, shows exactly the markers of the plot.
inline constexpr const char* kHollowCircle = "○";
inline constexpr const char* kFilledCircle = "●";
inline constexpr const char* kDiamond = "◆";
inline constexpr double kMarkerFont = 15;
const char* seriesGlyph(std::size_t index);

// Needs usePlotCoordinates(); x, y in world units.
void drawMarkers(const Frame& frame, const std::vector<double>& x, const std::vector<double>& y, const char* glyph,
                 int colour, double fontPx = kMarkerFont);

struct LegendEntry {
    std::string text;  // PLplot text
    int colour = 0;
    const char* glyph = kFilledCircle;
    bool line = false;  // a line sample under the glyph
    double glyphPx = kMarkerFont;  // the glyph's size on the plot, so both look alike
};
// Inside the plot, in the corner with the fewest markers; returns the legend's box.
Box drawLegend(const Frame& frame, const std::vector<LegendEntry>& entries, const std::vector<PagePoint>& markers);

struct LabelRequest {
    PagePoint anchor;  // the marker's centre
    std::string text;  // PLplot text
};
// Greedy, in request order: each label takes the spot beside its marker (right, left, above,
// below, diagonals) that stays inside the plot and covers least of the boxes placed so far,
// `obstacles` and the markers. Draws them.
void drawLabels(const Frame& frame, const std::vector<LabelRequest>& labels, std::vector<Box> obstacles,
                const std::vector<PagePoint>& markers);

}  // namespace st::report::detail
