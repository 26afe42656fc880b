#include "check/image_diff.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace st::check {
namespace {
int pixelDiff(const Rgba8Image& a, const Rgba8Image& b, std::size_t i) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.pixels[i * 4 + c]) - int(b.pixels[i * 4 + c])));
    return d;
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %%", share * 100.0);
    return text;
}

}  // namespace

std::string ImageTolerance::describe() const {
    std::string s = std::to_string(maxChannelDiff) + "/255 per channel, at most " + percent(maxFailingShare) + " of pixels";
    return s;
}

std::string ImageDiff::summary() const {
    if (!sizeMatches) return "the image sizes differ";
    std::string s = std::to_string(failingPixels) + " pixels (" + percent(failingShare) + ") over tolerance, max channel diff " +
                    std::to_string(maxChannelDiff);
    return s;
}

ImageDiff diffImages(const Rgba8Image& a, const Rgba8Image& b, const ImageTolerance& tol) {
    ImageDiff r;
    r.sizeMatches = a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size();
    if (!r.sizeMatches) return r;
    const std::size_t n = std::size_t(a.width) * std::size_t(a.height);
    for (std::size_t i = 0; i < n; ++i) {
        const int d = pixelDiff(a, b, i);
        r.maxChannelDiff = std::max(r.maxChannelDiff, d);
        if (d > tol.maxChannelDiff) ++r.failingPixels;
    }
    r.failingShare = n ? double(r.failingPixels) / double(n) : 0.0;
    r.pass = r.failingShare <= tol.maxFailingShare;
    return r;
}

Rgba8Image diffPicture(const Rgba8Image& a, const Rgba8Image& b, const ImageTolerance& tol) {
    Rgba8Image d{a.width, a.height, std::vector<std::uint8_t>(a.pixels.size(), 128)};
    if (a.pixels.size() != b.pixels.size()) return d;
    for (std::size_t i = 0; i < a.pixels.size() / 4; ++i) {
        const int diff = pixelDiff(a, b, i);
        const auto v = static_cast<std::uint8_t>(std::min(255, diff * 8));
        const bool fail = diff > tol.maxChannelDiff;
        d.pixels[i * 4 + 0] = fail ? 255 : v;
        d.pixels[i * 4 + 1] = fail ? 0 : v;
        d.pixels[i * 4 + 2] = fail ? 0 : v;
        d.pixels[i * 4 + 3] = 255;
    }
    return d;
}

}  // namespace st::check
