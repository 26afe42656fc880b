#include "app/images/compare_images.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace st::app {
namespace {

constexpr int kGap = 4;                     // between the two pictures of side-by-side.png
constexpr Rgb8 kDivider{255, 255, 255};

Rgba8Image canvas(int width, int height) {
    Rgba8Image img{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4, 255)};
    for (std::size_t i = 0; i < img.pixels.size(); i += 4)
        std::copy(kStripBackground.begin(), kStripBackground.end(), img.pixels.begin() + std::ptrdiff_t(i));
    return img;
}

std::uint8_t* at(Rgba8Image& img, int x, int y) { return &img.pixels[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4]; }
const std::uint8_t* at(const Rgba8Image& img, int x, int y) {
    return &img.pixels[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
}

// Columns [x0, x1) of `src` into `dst` at the same columns shifted by dx, rows 0..src.height; opaque.
void blit(Rgba8Image& dst, const Rgba8Image& src, int x0, int x1, int dx) {
    for (int y = 0; y < src.height; ++y) {
        std::memcpy(at(dst, x0 + dx, y), at(src, x0, y), std::size_t(x1 - x0) * 4);
        for (int x = x0; x < x1; ++x) at(dst, x + dx, y)[3] = 255;
    }
}

void fill(Rgba8Image& img, int x0, int x1, int height, const Rgb8& c) {
    for (int y = 0; y < height; ++y)
        for (int x = x0; x < x1; ++x) std::copy(c.begin(), c.end(), at(img, x, y));
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f %%", 100.0 * share);
    return text;
}

}  // namespace

Rgba8Image sideBySideImage(const Rgba8Image& a, const Rgba8Image& b, const Strip& labelA, const Strip& labelB) {
    const int strip = std::max(stripHeight(labelA, a.width), stripHeight(labelB, b.width));
    const int pictures = std::max(a.height, b.height);
    Rgba8Image img = canvas(a.width + kGap + b.width, pictures + strip);
    blit(img, a, 0, a.width, 0);
    blit(img, b, 0, b.width, a.width + kGap);
    drawStrip(img, 0, pictures, a.width, strip, labelA);
    drawStrip(img, a.width + kGap, pictures, b.width, strip, labelB);
    return img;
}

SplitLayout splitLayout(int width, int height) { return {width / 2 - 1, width / 2 + 1, height}; }

Rgba8Image splitImage(const Rgba8Image& a, const Rgba8Image& b, const Strip& labelA, const Strip& labelB) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("split image: the two pictures differ in size");
    const SplitLayout l = splitLayout(a.width, a.height);
    const int leftWidth = l.x0, rightWidth = a.width - l.x1;
    const int strip = std::max(stripHeight(labelA, leftWidth), stripHeight(labelB, rightWidth));
    Rgba8Image img = canvas(a.width, a.height + strip);
    blit(img, a, 0, l.x0, 0);
    blit(img, b, l.x1, b.width, 0);
    fill(img, l.x0, l.x1, a.height + strip, kDivider);
    drawStrip(img, 0, a.height, leftWidth, strip, labelA);
    drawStrip(img, l.x1, a.height, rightWidth, strip, labelB);
    return img;
}

Rgb8 diffColour(metrics::DiffClass c) {
    switch (c) {
    case metrics::DiffClass::Unscored: return {44, 50, 66};
    case metrics::DiffClass::Neither: return {235, 235, 235};
    case metrics::DiffClass::Both: return {128, 128, 128};
    case metrics::DiffClass::OnlyA: return {255, 120, 0};
    case metrics::DiffClass::OnlyB: return {0, 120, 255};
    }
    return {255, 0, 255};
}

Rgba8Image shadowDiffImage(const metrics::ShadowDiff& d, const std::string& nameA, const std::string& nameB) {
    using metrics::DiffClass;
    const Strip legend{
        {"unfiltered shadow test: A = " + nameA + ", B = " + nameB, std::nullopt, true},
        {"only A shadows " + percent(d.share(d.onlyA)), diffColour(DiffClass::OnlyA), false, true},
        {"only B shadows " + percent(d.share(d.onlyB)), diffColour(DiffClass::OnlyB)},
        {"both shadow " + percent(d.share(d.both)), diffColour(DiffClass::Both)},
        {"neither " + percent(d.share(d.neither)), diffColour(DiffClass::Neither)},
        {"not scored (no surface, faces away)", diffColour(DiffClass::Unscored)},
    };
    const int strip = stripHeight(legend, d.width);
    Rgba8Image img = canvas(d.width, d.height + strip);
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const Rgb8 c = diffColour(d.classes[std::size_t(y) * std::size_t(d.width) + std::size_t(x)]);
            std::copy(c.begin(), c.end(), at(img, x, y));
        }
    drawStrip(img, 0, d.height, d.width, strip, legend);
    return img;
}

}  // namespace st::app
