#pragma once
// A metric image with its legend underneath: a label strip (label_strip.h) of one swatch per
// colour, its meaning and its pixel count, after a bold title.
#include "metrics/metric_images.h"
#include "renderer/image/image_io.h"

#include <string>
#include <vector>

namespace st::app {

// `image` on top, the legend strip below it at the image's width.
Rgba8Image withLegend(const Rgba8Image& image, const std::string& title, const std::vector<metrics::LegendEntry>& legend);

}  // namespace st::app
