#include "metrics/metric_images.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace st::metrics {
namespace {

using Rgb = glm::u8vec3;
constexpr Rgb kNoSurface{60, 70, 90};

Rgba8Image blank(int width, int height) {
    return {width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4, 255)};
}

void put(Rgba8Image& img, std::size_t i, Rgb c) {
    img.pixels[4 * i] = c.r;
    img.pixels[4 * i + 1] = c.g;
    img.pixels[4 * i + 2] = c.b;
}

Rgb classColor(PixelClass c) {
    switch (c) {
    case PixelClass::NoSurface: return kNoSurface;
    case PixelClass::FacingAway: return {30, 30, 36};
    case PixelClass::Terminator: return {70, 40, 90};
    case PixelClass::CorrectLit: return {205, 205, 205};
    case PixelClass::CorrectShadow: return {110, 110, 110};
    case PixelClass::FalseShadowEdge: return {255, 185, 150};
    case PixelClass::FalseShadowGross: return {230, 20, 20};
    case PixelClass::FalseLightEdge: return {150, 205, 255};
    case PixelClass::FalseLightGross: return {20, 60, 255};
    }
    return {255, 0, 255};
}

// main.frag's texelDensityColor ramp, sRGB-encoded like the view.
Rgb densityColor(float pixelsPerTexel) {
    const float v = std::clamp(std::log2(std::max(pixelsPerTexel, 1e-12f)) / 4.0f, -1.0f, 1.0f);
    const glm::vec3 ideal(0.0f, 0.8f, 0.1f);
    const glm::vec3 c = v < 0.0f ? glm::mix(ideal, glm::vec3(0.1f, 0.2f, 1.0f), -v)
                                 : glm::mix(ideal, glm::vec3(1.0f, 0.1f, 0.0f), v);
    return Rgb(glm::pow(c, glm::vec3(1.0f / 2.2f)) * 255.0f + 0.5f);
}

}  // namespace

Rgba8Image truthImage(const MeasureSamples& s, const std::vector<std::uint8_t>& truth) {
    Rgba8Image img = blank(s.width, s.height);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.covered(i)) put(img, i, kNoSurface);
        else put(img, i, truth[i] ? Rgb{240, 240, 240} : Rgb{50, 50, 50});
    }
    return img;
}

Rgba8Image errorImage(const AccuracyReport& a, int width, int height) {
    Rgba8Image img = blank(width, height);
    for (std::size_t i = 0; i < a.classes.size(); ++i) put(img, i, classColor(a.classes[i]));
    return img;
}

Rgba8Image densityImage(const MeasureSamples& s) {
    Rgba8Image img = blank(s.width, s.height);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.covered(i)) put(img, i, kNoSurface);
        else put(img, i, s.cascade(i) < 0 ? Rgb{128, 128, 128} : densityColor(s.shadow[i].w));
    }
    return img;
}

Rgba8Image flickerImage(const std::vector<float>& stdDev, const MeasureSamples& s) {
    Rgba8Image img = blank(s.width, s.height);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const float t = std::clamp(stdDev[i] / 0.5f, 0.0f, 1.0f);
        put(img, i, s.covered(i) ? Rgb(glm::mix(glm::vec3(50.0f), glm::vec3(255.0f, 230.0f, 40.0f), t)) : kNoSurface);
    }
    return img;
}

}  // namespace st::metrics
