#include "app/images/label_strip.h"

#include "report/chart_fonts.h"

#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

namespace st::app {
namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

// Where each item goes: its pen position (left edge, line index).
struct Placed {
    double x = 0.0;
    int line = 0;
};

struct Metrics {
    double font = 12.0;
    double pad = 4.0;
    double lineHeight = 14.0;
    double ascent = 10.0;
    double swatch = 10.0;  // side of a swatch square
    double gap = 12.0;     // between items on a line
};

void selectFont(cairo_t* cr, double px, bool bold) {
    cairo_select_font_face(cr, report::kSansFamily, CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, px);
}

Metrics metricsFor(cairo_t* cr, int width) {
    report::warnAboutMissingChartFonts();
    Metrics m;
    m.font = stripFontPx(width);
    selectFont(cr, m.font, false);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    m.pad = std::round(m.font * 0.4);
    m.lineHeight = std::ceil(fe.height * 1.05);
    m.ascent = std::ceil(fe.ascent);
    m.swatch = std::round(m.font * 0.85);
    m.gap = std::round(m.font * 1.0);
    return m;
}

double itemWidth(cairo_t* cr, const Metrics& m, const StripItem& item) {
    selectFont(cr, m.font, item.bold);
    cairo_text_extents_t te;
    cairo_text_extents(cr, item.text.c_str(), &te);
    return te.x_advance + (item.swatch ? m.swatch + m.font * 0.35 : 0.0);
}

// Words of `text`, packed greedily into pieces at most `room` wide (a lone longer word is a piece).
std::vector<std::string> packWords(cairo_t* cr, const Metrics& m, const StripItem& item, double room) {
    std::vector<std::string> pieces;
    std::size_t start = 0;
    while (start < item.text.size()) {
        std::size_t end = item.text.find(' ', start);
        if (end == std::string::npos) end = item.text.size();
        const std::string word = item.text.substr(start, end - start);
        StripItem trial = item;
        trial.text = pieces.empty() ? word : pieces.back() + " " + word;
        if (!pieces.empty() && itemWidth(cr, m, trial) <= room)
            pieces.back() = trial.text;
        else
            pieces.push_back(word);
        start = end + 1;
    }
    return pieces;
}

// Items wider than the band are cut at spaces into pieces, each on a line of its own; the
// swatch stays with the first piece.
Strip fitToWidth(cairo_t* cr, const Metrics& m, const Strip& strip, int width) {
    const double room = width - 2 * m.pad;
    Strip fitted;
    for (const StripItem& item : strip) {
        if (itemWidth(cr, m, item) <= room) {
            fitted.push_back(item);
            continue;
        }
        const std::vector<std::string> pieces = packWords(cr, m, item, room);
        for (std::size_t i = 0; i < pieces.size(); ++i)
            fitted.push_back({pieces[i], i == 0 ? item.swatch : std::nullopt, item.bold, true});
    }
    return fitted;
}

// Greedy flow: an item that would overrun the band starts a new line (unless it is the first
// on its line, which then overruns and is clipped).
std::vector<Placed> layout(cairo_t* cr, const Metrics& m, const Strip& strip, int width) {
    std::vector<Placed> placed;
    double x = m.pad;
    int line = 0;
    for (const StripItem& item : strip) {
        const double w = itemWidth(cr, m, item);
        const bool first = x == m.pad;
        if (!placed.empty() && (item.newLine || (!first && x + w > width - m.pad))) {
            ++line;
            x = m.pad;
        }
        placed.push_back({x, line});
        x += w + m.gap;
    }
    return placed;
}

int heightOf(const Metrics& m, const std::vector<Placed>& placed) {
    const int lines = placed.empty() ? 1 : placed.back().line + 1;
    return int(std::ceil(2 * m.pad + lines * m.lineHeight));
}

Surface scratchSurface() { return {cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1), &cairo_surface_destroy}; }

// cairo's ARGB32 is BGRA in memory on little-endian machines; the images are opaque, so
// premultiplication changes nothing and swapping R and B converts both ways.
void swapRedBlue(Rgba8Image& img) {
    for (std::size_t i = 0; i + 3 < img.pixels.size(); i += 4) std::swap(img.pixels[i], img.pixels[i + 2]);
}

void setColour(cairo_t* cr, const Rgb8& c) { cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0); }

void drawItem(cairo_t* cr, const Metrics& m, const StripItem& item, double x, double top) {
    const double baseline = top + m.ascent;
    if (item.swatch) {
        const double y = baseline - m.swatch + std::round(m.font * 0.1);
        cairo_rectangle(cr, x + 0.5, y + 0.5, m.swatch - 1.0, m.swatch - 1.0);
        setColour(cr, *item.swatch);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
        cairo_set_line_width(cr, 1.0);
        cairo_stroke(cr);
        x += m.swatch + m.font * 0.35;
    }
    selectFont(cr, m.font, item.bold);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_move_to(cr, x, baseline);
    cairo_show_text(cr, item.text.c_str());
}

void drawOnto(cairo_t* cr, int x, int y, int width, int height, const Strip& strip) {
    cairo_rectangle(cr, x, y, width, height);
    cairo_clip(cr);
    setColour(cr, kStripBackground);
    cairo_paint(cr);
    cairo_translate(cr, x, y);
    const Metrics m = metricsFor(cr, width);
    const Strip fitted = fitToWidth(cr, m, strip, width);
    const std::vector<Placed> placed = layout(cr, m, fitted, width);
    for (std::size_t i = 0; i < fitted.size(); ++i)
        drawItem(cr, m, fitted[i], placed[i].x, m.pad + placed[i].line * m.lineHeight);
}

}  // namespace

double stripFontPx(int width) { return std::clamp(std::round(width / 42.0), 11.0, 18.0); }

int stripHeight(const Strip& strip, int width) {
    const Surface surface = scratchSurface();
    const Context cr{cairo_create(surface.get()), &cairo_destroy};
    const Metrics m = metricsFor(cr.get(), width);
    return heightOf(m, layout(cr.get(), m, fitToWidth(cr.get(), m, strip, width), width));
}

void drawStrip(Rgba8Image& img, int x, int y, int width, int height, const Strip& strip) {
    swapRedBlue(img);
    const Surface surface{cairo_image_surface_create_for_data(img.pixels.data(), CAIRO_FORMAT_ARGB32, img.width,
                                                              img.height, img.width * 4),
                          &cairo_surface_destroy};
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error("cairo: cannot draw onto the image");
    {
        const Context cr{cairo_create(surface.get()), &cairo_destroy};
        cairo_set_antialias(cr.get(), CAIRO_ANTIALIAS_GRAY);
        drawOnto(cr.get(), x, y, width, height, strip);
    }
    cairo_surface_flush(surface.get());
    swapRedBlue(img);
}

void releaseTextCaches() {
    cairo_debug_reset_static_data();
    FcFini();
}

}  // namespace st::app
