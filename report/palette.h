#pragma once
// Colour map 0 of every chart (report/ internals): indices passed to plcol0(), pllegend().
#include <array>
#include <cstdint>

namespace st::report::detail {

enum Colour : int {
    kBackground = 0,  // PLplot clears the page with colour 0
    kInk = 1,         // axes, text
    kGrid = 2,
    kMutedInk = 3,    // subtitle, table separators
    kAllPoints = 4,
    kFront = 5,
    kReference = 6,
    kSeries0 = 7,     // line-chart series cycle through kSeriesCount colours from here
};
inline constexpr int kSeriesCount = 8;

struct Rgb { std::uint8_t r, g, b; };
// Series colours after matplotlib's "tab10": distinct and readable on white.
inline constexpr std::array<Rgb, kSeries0 + kSeriesCount> kPalette{{
    {255, 255, 255}, {34, 34, 34}, {225, 225, 225}, {110, 110, 110},
    {76, 114, 176}, {214, 39, 40}, {44, 160, 44},
    {31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
    {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127},
}};

}  // namespace st::report::detail
