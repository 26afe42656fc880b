#include "tests/support/image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace st::test {
namespace {
int pixelDiff(const Rgba8Image& a, const Rgba8Image& b, std::size_t i) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.pixels[i * 4 + c]) - int(b.pixels[i * 4 + c])));
    return d;
}
}  // namespace

std::string CompareResult::summary() const {
    std::ostringstream s;
    if (!sizeMatches) return "image sizes differ";
    s << failingPixels << " pixels (" << failingFraction * 100.0 << " %) over tolerance, max channel diff "
      << maxChannelDiff;
    return s.str();
}

CompareResult compareImages(const Rgba8Image& a, const Rgba8Image& b, const Tolerance& tol) {
    CompareResult r;
    r.sizeMatches = a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size();
    if (!r.sizeMatches) return r;
    std::size_t n = std::size_t(a.width) * a.height;
    for (std::size_t i = 0; i < n; ++i) {
        int d = pixelDiff(a, b, i);
        r.maxChannelDiff = std::max(r.maxChannelDiff, d);
        if (d > tol.maxChannelDiff) ++r.failingPixels;
    }
    r.failingFraction = n ? double(r.failingPixels) / double(n) : 0.0;
    r.pass = r.failingFraction <= tol.maxFailingFraction;
    return r;
}

Rgba8Image diffImage(const Rgba8Image& a, const Rgba8Image& b, const Tolerance& tol) {
    Rgba8Image d{a.width, a.height, std::vector<std::uint8_t>(a.pixels.size(), 255)};
    if (a.pixels.size() != b.pixels.size()) return d;
    for (std::size_t i = 0; i < a.pixels.size() / 4; ++i) {
        int diff = pixelDiff(a, b, i);
        auto v = static_cast<std::uint8_t>(std::min(255, diff * 8));
        bool fail = diff > tol.maxChannelDiff;
        d.pixels[i * 4 + 0] = fail ? 255 : v;
        d.pixels[i * 4 + 1] = fail ? 0 : v;
        d.pixels[i * 4 + 2] = fail ? 0 : v;
    }
    return d;
}

Rgba8Image shifted(const Rgba8Image& img, int dx, int dy) {
    Rgba8Image out = img;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            int sx = std::clamp(x - dx, 0, img.width - 1), sy = std::clamp(y - dy, 0, img.height - 1);
            std::copy_n(&img.pixels[(std::size_t(sy) * img.width + sx) * 4], 4,
                        &out.pixels[(std::size_t(y) * img.width + x) * 4]);
        }
    return out;
}

}  // namespace st::test
