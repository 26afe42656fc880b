#include "metrics/soft_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace st::metrics {
namespace {

constexpr float kFar = 1e9f;

// Pixels of one truth region, as the source of a distance map. Facing-away pixels are in
// shadow in truth (as truthEdges() counts them), empty pixels are no edge at all.
std::vector<std::uint8_t> region(const MeasureSamples& s, const SoftTruth& t, bool (*in)(float visible)) {
    std::vector<std::uint8_t> out(s.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.covered(i)) continue;
        out[i] = in(s.receiver(i) ? t.visible[i] : 0.0f);
    }
    return out;
}

// Pixels per texel across at pixel i: shadow.w is the screen area one texel covers.
float texelPx(const MeasureSamples& s, std::size_t i) {
    return s.cascade(i) >= 0 ? std::sqrt(std::max(s.shadow[i].w, 0.0f)) : 1.0f;
}

// Labels of the 4-connected regions of true shadow (receivers with t < 0.5), -1 elsewhere.
std::vector<int> shadowRegions(const MeasureSamples& s, const SoftTruth& t, int& count) {
    std::vector<int> label(s.size(), -1);
    count = 0;
    std::vector<std::size_t> stack;
    auto inShadow = [&](std::size_t i) { return s.receiver(i) && t.visible[i] < 0.5f; };
    for (std::size_t seed = 0; seed < s.size(); ++seed) {
        if (label[seed] >= 0 || !inShadow(seed)) continue;
        stack.assign(1, seed);
        label[seed] = count;
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            const int x = int(i % std::size_t(s.width)), y = int(i / std::size_t(s.width));
            const std::size_t next[4] = {i - 1, i + 1, i - std::size_t(s.width), i + std::size_t(s.width)};
            const bool ok[4] = {x > 0, x + 1 < s.width, y > 0, y + 1 < s.height};
            for (int n = 0; n < 4; ++n) {
                if (!ok[n] || label[next[n]] >= 0 || !inShadow(next[n])) continue;
                label[next[n]] = count;
                stack.push_back(next[n]);
            }
        }
        ++count;
    }
    return label;
}

}  // namespace

void ArtifactCounts::add(ArtifactClass c, double absError) {
    ++receivers;
    filteredAbsErrorSum += absError;
    edge += c == ArtifactClass::Edge;
    acne += c == ArtifactClass::Acne;
    lightBleeding += c == ArtifactClass::LightBleeding;
    peterPanning += c == ArtifactClass::PeterPanning;
    missingCaster += c == ArtifactClass::MissingCaster;
}

std::vector<float> distanceToNearest(int width, int height, const std::vector<std::uint8_t>& source) {
    // Two passes of the 3-4 chamfer (Borgefors 1986, "Distance transformations in digital
    // images", §4), in thirds of a pixel.
    std::vector<float> d(source.size());
    for (std::size_t i = 0; i < source.size(); ++i) d[i] = source[i] ? 0.0f : kFar;
    auto at = [&](int x, int y) -> float& { return d[std::size_t(y) * std::size_t(width) + std::size_t(x)]; };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float& v = at(x, y);
            if (x > 0) v = std::min(v, at(x - 1, y) + 3.0f);
            if (y > 0) {
                v = std::min(v, at(x, y - 1) + 3.0f);
                if (x > 0) v = std::min(v, at(x - 1, y - 1) + 4.0f);
                if (x + 1 < width) v = std::min(v, at(x + 1, y - 1) + 4.0f);
            }
        }
    }
    for (int y = height - 1; y >= 0; --y) {
        for (int x = width - 1; x >= 0; --x) {
            float& v = at(x, y);
            if (x + 1 < width) v = std::min(v, at(x + 1, y) + 3.0f);
            if (y + 1 < height) {
                v = std::min(v, at(x, y + 1) + 3.0f);
                if (x + 1 < width) v = std::min(v, at(x + 1, y + 1) + 4.0f);
                if (x > 0) v = std::min(v, at(x - 1, y + 1) + 4.0f);
            }
        }
    }
    for (float& v : d) v = v >= kFar ? kFar : v / 3.0f;
    return d;
}

void penumbraWidth(const MeasureSamples& s, const std::vector<float>& f, const std::vector<std::uint8_t>& use,
                   float kEps, double& widthPx, std::size_t& pixels, std::size_t& contour) {
    pixels = contour = 0;
    auto used = [&](std::size_t i) { return s.receiver(i) && (use.empty() || use[i]); };
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(s.width) + std::size_t(x);
            if (!used(i)) continue;
            pixels += f[i] > kEps && f[i] < 1.0f - kEps;
            if (f[i] < 0.5f) continue;
            auto below = [&](std::size_t n) { return used(n) && f[n] < 0.5f; };
            contour += (x > 0 && below(i - 1)) || (x + 1 < s.width && below(i + 1)) ||
                       (y > 0 && below(i - std::size_t(s.width))) || (y + 1 < s.height && below(i + std::size_t(s.width)));
        }
    }
    widthPx = contour ? double(pixels) / double(contour) : 0.0;
}

SoftTruthRegions softTruthRegions(const MeasureSamples& s, const SoftTruth& t) {
    SoftTruthRegions g;
    // Distance from lit pixels to the nearest not fully lit one, and from umbra pixels to the
    // nearest not fully shadowed one: how far inside its region a pixel is.
    g.toShadow = distanceToNearest(s.width, s.height, region(s, t, [](float v) { return v < 1.0f; }));
    g.toLight = distanceToNearest(s.width, s.height, region(s, t, [](float v) { return v > 0.0f; }));
    int regionCount = 0;
    g.label = shadowRegions(s, t, regionCount);
    g.regionSize.assign(std::size_t(regionCount), 0);
    for (const int l : g.label)
        if (l >= 0) ++g.regionSize[std::size_t(l)];
    penumbraWidth(s, t.visible, {}, 0.0f, g.truthPenumbra.truthPx, g.truthPenumbra.truthPixels,
                  g.truthPenumbra.truthContour);
    return g;
}

SoftAccuracyReport scoreSoftAccuracy(const MeasureSamples& s, const SoftTruth& t,
                                     const std::vector<float>& texelWorldSize, const ArtifactParams& p) {
    return scoreSoftAccuracy(s, t, softTruthRegions(s, t), texelWorldSize, p);
}

SoftAccuracyReport scoreSoftAccuracy(const MeasureSamples& s, const SoftTruth& t, const SoftTruthRegions& g,
                                     const std::vector<float>& texelWorldSize, const ArtifactParams& p) {
    SoftAccuracyReport r;
    r.cascades.resize(texelWorldSize.size());
    r.classes.assign(s.size(), ArtifactClass::NotScored);
    const std::vector<float>& toShadow = g.toShadow;
    const std::vector<float>& toLight = g.toLight;
    const std::vector<int>& label = g.label;
    const std::vector<std::size_t>& size = g.regionSize;
    std::vector<std::size_t> light(size.size(), 0);
    auto tooLight = [&](std::size_t i) { return s.shadow[i].y > t.visible[i] + p.tolerance; };
    for (std::size_t i = 0; i < s.size(); ++i)
        if (label[i] >= 0) light[std::size_t(label[i])] += tooLight(i);

    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.receiver(i)) continue;
        const float f = s.shadow[i].y, v = t.visible[i];
        const int c = s.cascade(i);
        const float kPx = p.k * texelPx(s, i);
        ArtifactClass k = ArtifactClass::Correct;
        if (f < v - p.tolerance) {
            k = v >= 1.0f && toShadow[i] > kPx ? ArtifactClass::Acne : ArtifactClass::Edge;
        } else if (f > v + p.tolerance) {
            const int l = label[i];
            const float texelM = c >= 0 && std::size_t(c) < texelWorldSize.size() ? texelWorldSize[std::size_t(c)] : 0.0f;
            if (l >= 0 && double(light[std::size_t(l)]) >= double(p.missingShare) * double(size[std::size_t(l)]))
                k = ArtifactClass::MissingCaster;
            else if (v < 1.0f && t.blocker[i] <= p.k * texelM)
                k = ArtifactClass::PeterPanning;
            else if (v <= 0.0f && toLight[i] > kPx)
                k = ArtifactClass::LightBleeding;
            else
                k = ArtifactClass::Edge;
        }
        r.classes[i] = k;
        const double err = std::abs(double(f) - double(v));
        r.all.add(k, err);
        if (c >= 0 && std::size_t(c) < r.cascades.size()) r.cascades[std::size_t(c)].add(k, err);
    }

    std::vector<float> filtered(s.size(), 0.0f);
    std::vector<std::uint8_t> penumbraUse(s.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        filtered[i] = s.shadow[i].y;
        const ArtifactClass k = r.classes[i];
        // Greys far out in the light are the kernel's speckle, not a penumbra.
        const bool nearShadow = t.visible[i] < 1.0f || toShadow[i] <= p.k * texelPx(s, i);
        penumbraUse[i] =
            nearShadow && (k == ArtifactClass::Correct || k == ArtifactClass::Edge || k == ArtifactClass::PeterPanning);
    }
    r.penumbra = g.truthPenumbra;
    penumbraWidth(s, filtered, penumbraUse, 0.02f, r.penumbra.filteredPx, r.penumbra.filteredPixels, r.penumbra.filteredContour);
    return r;
}

}  // namespace st::metrics
