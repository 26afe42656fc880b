#pragma once
// A rendered image against its golden, after Filament's renderdiff: a pixel fails when any
// channel differs by more than max_channel_diff; the image fails when more than
// max_failing_share of its pixels fail. No perceptual measure: the one a Debian library offers,
// OpenImageIO's compare_Yee (2.4), finds no failing pixel even for a white block on grey (it never
// tests luminance; tests/check/perceptual_library_test.cpp shows it and fails once it does).
#include "renderer/image/image_io.h"

#include <optional>
#include <string>

namespace st::check {

struct ImageTolerance {
    int maxChannelDiff = 5;                      // of 255: llvmpipe's rounding between builds
    double maxFailingShare = 0.001;              // 0.1 %: a few edge pixels may flip
    std::string describe() const;  // "5/255 per channel, at most 0.1 % of pixels"
};

struct ImageDiff {
    bool sizeMatches = false;
    int maxChannelDiff = 0;
    std::size_t failingPixels = 0;
    double failingShare = 1.0;
    bool pass = false;
    std::string summary() const;  // "12 pixels (0.021 %) over 5/255, max channel diff 40"
};

ImageDiff diffImages(const Rgba8Image& actual, const Rgba8Image& golden, const ImageTolerance& tol);

// Per-pixel |a-b| scaled up (x8) so small differences show, red where a pixel fails; a grey
// image of the actual's size when the sizes differ.
Rgba8Image diffPicture(const Rgba8Image& actual, const Rgba8Image& golden, const ImageTolerance& tol);

}  // namespace st::check
