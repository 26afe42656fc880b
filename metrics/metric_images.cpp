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
    case PixelClass::FalseShadowEdge: return {250, 175, 240};
    case PixelClass::FalseShadowGross: return {220, 20, 200};
    case PixelClass::FalseLightEdge: return {165, 240, 240};
    case PixelClass::FalseLightGross: return {0, 205, 215};
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

// Over a lit scene errorImage's pale edge colours are about as bright as the ground: these are
// darker, and keep the hues.
Rgb overlayColor(PixelClass c) {
    if (c == PixelClass::FalseShadowEdge) return {240, 110, 225};
    if (c == PixelClass::FalseLightEdge) return {90, 225, 230};
    return classColor(c);
}

bool isGross(PixelClass c) { return c == PixelClass::FalseShadowGross || c == PixelClass::FalseLightGross; }
bool isError(PixelClass c) { return isGross(c) || c == PixelClass::FalseShadowEdge || c == PixelClass::FalseLightEdge; }

// A translucent ring in gross pixel i's colour over its transparent 8-neighbours.
void halo(Rgba8Image& img, std::size_t i, Rgb colour) {
    const int x = int(i % std::size_t(img.width)), y = int(i / std::size_t(img.width));
    for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, img.height - 1); ++ny) {
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, img.width - 1); ++nx) {
            const std::size_t n = std::size_t(ny) * std::size_t(img.width) + std::size_t(nx);
            if (img.pixels[4 * n + 3] != 0) continue;
            put(img, n, colour);
            img.pixels[4 * n + 3] = 110;
        }
    }
}

std::array<std::uint8_t, 3> bytes(Rgb c) { return {c.r, c.g, c.b}; }

constexpr Rgb kAcne{235, 25, 25}, kBleeding{255, 150, 0}, kPeterPanning{225, 40, 225}, kMissing{30, 70, 255},
    kEdge{245, 235, 150}, kLit{215, 215, 215}, kPenumbra{150, 150, 150}, kUmbra{85, 85, 85};

Rgb artifactColor(ArtifactClass c, float truth) {
    switch (c) {
    case ArtifactClass::NotScored: return kNoSurface;
    case ArtifactClass::Correct: return truth >= 1.0f ? kLit : truth <= 0.0f ? kUmbra : kPenumbra;
    case ArtifactClass::Edge: return kEdge;
    case ArtifactClass::Acne: return kAcne;
    case ArtifactClass::LightBleeding: return kBleeding;
    case ArtifactClass::PeterPanning: return kPeterPanning;
    case ArtifactClass::MissingCaster: return kMissing;
    }
    return {255, 0, 255};
}

}  // namespace

std::vector<LegendEntry> errorLegend(const AccuracyReport& a) {
    std::vector<LegendEntry> out;
    const std::pair<PixelClass, const char*> rows[] = {
        {PixelClass::FalseShadowGross, "false shadow, gross (acne)"}, {PixelClass::FalseShadowEdge, "false shadow at an edge"},
        {PixelClass::FalseLightGross, "false light, gross (leak, missing caster)"},
        {PixelClass::FalseLightEdge, "false light at an edge"},       {PixelClass::CorrectLit, "lit, correct"},
        {PixelClass::CorrectShadow, "shadow, correct"},              {PixelClass::FacingAway, "facing away"},
        {PixelClass::Terminator, "terminator"},                      {PixelClass::NoSurface, "no surface"}};
    for (const auto& [c, name] : rows) {
        const std::size_t n = std::size_t(std::count(a.classes.begin(), a.classes.end(), c));
        out.push_back({name, bytes(classColor(c)), n});
    }
    return out;
}

Rgba8Image artifactImage(const MeasureSamples& s, const SoftTruth& t, const SoftAccuracyReport& r) {
    Rgba8Image img = blank(s.width, s.height);
    for (std::size_t i = 0; i < r.classes.size(); ++i) put(img, i, artifactColor(r.classes[i], t.visible[i]));
    return img;
}

std::vector<LegendEntry> artifactLegend(const SoftTruth& t, const SoftAccuracyReport& r) {
    std::vector<LegendEntry> out{{"acne", bytes(kAcne), 0},
                                 {"light bleeding", bytes(kBleeding), 0},
                                 {"peter-panning", bytes(kPeterPanning), 0},
                                 {"missing caster", bytes(kMissing), 0},
                                 {"edge error", bytes(kEdge), 0},
                                 {"correct, lit", bytes(kLit), 0},
                                 {"correct, penumbra", bytes(kPenumbra), 0},
                                 {"correct, umbra", bytes(kUmbra), 0},
                                 {"not scored", bytes(kNoSurface), 0}};
    for (std::size_t i = 0; i < r.classes.size(); ++i) {
        const std::array<std::uint8_t, 3> c = bytes(artifactColor(r.classes[i], t.visible[i]));
        for (LegendEntry& e : out) e.pixels += e.colour == c;
    }
    return out;
}

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

Rgba8Image errorOverlayImage(const AccuracyReport& a, int width, int height) {
    Rgba8Image img{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4, 0)};
    for (std::size_t i = 0; i < a.classes.size(); ++i) {
        if (!isError(a.classes[i])) continue;
        put(img, i, overlayColor(a.classes[i]));
        img.pixels[4 * i + 3] = 255;
    }
    for (std::size_t i = 0; i < a.classes.size(); ++i)  // after every error pixel is opaque: rings never cover one
        if (isGross(a.classes[i])) halo(img, i, overlayColor(a.classes[i]));
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
