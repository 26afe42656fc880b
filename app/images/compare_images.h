#pragma once
// The images of `shadowtune compare`, composed from two RGBA8 frames, with labels and a legend
// drawn by cairo (a sans font; white text on a dark strip below the pictures, so no picture
// pixel is covered except by the split view's divider). No GL.
#include "metrics/compare.h"
#include "app/images/label_strip.h"
#include "renderer/image/image_io.h"

#include <string>

namespace st::app {

// A and B next to each other (a 4 px gap), each with its own strip below it.
Rgba8Image sideBySideImage(const Rgba8Image& a, const Rgba8Image& b, const Strip& labelA, const Strip& labelB);

// Where the split view's divider covers the picture: columns [x0, x1) of its first `height` rows.
struct SplitLayout {
    int x0 = 0, x1 = 0, height = 0;
};
SplitLayout splitLayout(int width, int height);
// One picture: A's columns left of the divider, B's right of it (same size required), each
// half's strip below it. Throws std::invalid_argument on a size mismatch.
Rgba8Image splitImage(const Rgba8Image& a, const Rgba8Image& b, const Strip& labelA, const Strip& labelB);

// The shadow-diff colours, one per DiffClass.
Rgb8 diffColour(metrics::DiffClass c);
// The classes as colours, with a legend strip below (swatches, names and shares).
Rgba8Image shadowDiffImage(const metrics::ShadowDiff& d, const std::string& nameA, const std::string& nameB);

}  // namespace st::app
