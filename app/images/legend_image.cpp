#include "app/images/legend_image.h"

#include "app/images/label_strip.h"

#include <algorithm>

namespace st::app {

Rgba8Image withLegend(const Rgba8Image& image, const std::string& title, const std::vector<metrics::LegendEntry>& legend) {
    Strip strip{{.text = title, .bold = true}};
    for (const metrics::LegendEntry& e : legend)
        strip.push_back({.text = e.name + " " + std::to_string(e.pixels) + " px", .swatch = e.colour});
    const int stripPx = stripHeight(strip, image.width);
    Rgba8Image out{image.width, image.height + stripPx,
                   std::vector<std::uint8_t>(std::size_t(image.width) * std::size_t(image.height + stripPx) * 4, 255)};
    std::copy(image.pixels.begin(), image.pixels.end(), out.pixels.begin());
    drawStrip(out, 0, image.height, image.width, stripPx, strip);
    return out;
}

}  // namespace st::app
