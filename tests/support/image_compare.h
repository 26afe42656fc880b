#pragma once
// Golden-image comparison with explicit tolerances (after Filament's renderdiff: a pixel fails
// when any channel differs by more than maxChannelDiff; the image fails when more than
// maxFailingFraction of its pixels fail).
#include "renderer/image/image_io.h"

#include <filesystem>
#include <string>

namespace st::test {

struct Tolerance {
    int maxChannelDiff = 5;              // of 255: llvmpipe rounding between builds
    double maxFailingFraction = 0.001;   // 0.1 %: a few edge pixels may flip
};

struct CompareResult {
    bool sizeMatches = false;
    int maxChannelDiff = 0;
    std::size_t failingPixels = 0;
    double failingFraction = 1.0;
    bool pass = false;
    std::string summary() const;
};

CompareResult compareImages(const Rgba8Image& actual, const Rgba8Image& golden, const Tolerance& tol);

// Per-pixel |a-b| scaled up (x8) so small differences show, red where a pixel fails.
Rgba8Image diffImage(const Rgba8Image& actual, const Rgba8Image& golden, const Tolerance& tol);

Rgba8Image shifted(const Rgba8Image& img, int dx, int dy);  // edge pixels repeat

}  // namespace st::test
