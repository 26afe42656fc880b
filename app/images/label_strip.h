#pragma once
// Label strips drawn with cairo onto RGBA8 images: white text in DejaVu Sans (report/chart_fonts.h)
// and colour swatches on a dark band, wrapped to the band's width. The text size follows the
// image width. No GL.
#include "renderer/image/image_io.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

using Rgb8 = std::array<std::uint8_t, 3>;

// One piece of a strip: text, optionally after a colour swatch. Pieces flow left to right and
// wrap onto new lines; `newLine` starts one.
struct StripItem {
    std::string text;
    std::optional<Rgb8> swatch;
    bool bold = false;
    bool newLine = false;
};
using Strip = std::vector<StripItem>;

inline constexpr Rgb8 kStripBackground{28, 30, 36};

// Text size for a strip `width` pixels wide: 11..18 px.
double stripFontPx(int width);
// Height in pixels of `strip` laid out in a band `width` pixels wide.
int stripHeight(const Strip& strip, int width);
// Fills columns [x, x + width) of rows [y, y + height) of `img` with the dark band and draws
// `strip` onto it (laid out as stripHeight() does).
void drawStrip(Rgba8Image& img, int x, int y, int width, int height, const Strip& strip);

// Frees cairo's and fontconfig's process-wide font caches, which LeakSanitizer otherwise reports
// at exit. Call when no strip will be drawn for a while (they are rebuilt on the next use).
void releaseTextCaches();

}  // namespace st::app
