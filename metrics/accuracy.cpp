#include "metrics/accuracy.h"

#include "metrics/parallel_rows.h"

#include <algorithm>
#include <cmath>

namespace st::metrics {
namespace {

PixelClass classify(bool truthLit, bool mapLit, bool resolutionExplains) {
    if (truthLit == mapLit) return truthLit ? PixelClass::CorrectLit : PixelClass::CorrectShadow;
    if (mapLit) return resolutionExplains ? PixelClass::FalseLightEdge : PixelClass::FalseLightGross;
    return resolutionExplains ? PixelClass::FalseShadowEdge : PixelClass::FalseShadowGross;
}

PixelClass classifyPixel(const MeasureSamples& s, const std::vector<std::uint8_t>& truth, std::size_t i,
                         const ResolutionExplains& explains) {
    if (!s.covered(i)) return PixelClass::NoSurface;
    if (s.terminator(i)) return PixelClass::Terminator;
    if (!s.receiver(i)) return PixelClass::FacingAway;
    const bool truthLit = truth[i] != 0;
    const bool mapLit = s.shadow[i].x >= 0.5f;
    const bool edge = truthLit != mapLit && s.cascade(i) >= 0 && explains(i, mapLit);
    return classify(truthLit, mapLit, edge);
}

}  // namespace

void ErrorCounts::add(PixelClass c, double filteredAbsError) {
    ++receivers;
    filteredAbsErrorSum += filteredAbsError;
    if (c == PixelClass::FalseShadowEdge) ++falseShadowEdge;
    if (c == PixelClass::FalseShadowGross) ++falseShadowGross;
    if (c == PixelClass::FalseLightEdge) ++falseLightEdge;
    if (c == PixelClass::FalseLightGross) ++falseLightGross;
}

std::vector<std::uint8_t> truthEdges(const MeasureSamples& s, const std::vector<std::uint8_t>& truth) {
    std::vector<std::uint8_t> edges(s.size(), 0);
    auto differs = [&](std::size_t a, std::size_t b) { return s.covered(b) && truth[a] != truth[b]; };
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const std::size_t i = std::size_t(y) * s.width + x;
            if (!s.covered(i)) continue;
            edges[i] = (x > 0 && differs(i, i - 1)) || (x + 1 < s.width && differs(i, i + 1)) ||
                       (y > 0 && differs(i, i - s.width)) || (y + 1 < s.height && differs(i, i + s.width));
        }
    }
    return edges;
}

AccuracyReport scoreAccuracy(const MeasureSamples& s, const std::vector<std::uint8_t>& truth, int cascadeCount,
                             const ResolutionExplains& explains, const RowControl& control) {
    AccuracyReport r;
    r.cascades.resize(std::size_t(std::max(cascadeCount, 0)));
    r.classes.assign(s.size(), PixelClass::NoSurface);
    forEachRowParallel(s.height, [&](int y) {
        for (std::size_t i = std::size_t(y) * s.width, end = i + s.width; i < end; ++i)
            r.classes[i] = classifyPixel(s, truth, i, explains);
    }, control);
    if (control.cancelled()) return r;
    const std::vector<std::uint8_t> edges = truthEdges(s, truth);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const PixelClass c = r.classes[i];
        r.covered += c != PixelClass::NoSurface;
        r.facingAway += c == PixelClass::FacingAway;
        r.terminator += c == PixelClass::Terminator;
        r.edgePixels += edges[i];
        if (c == PixelClass::NoSurface || c == PixelClass::FacingAway || c == PixelClass::Terminator) continue;
        const double filteredError = std::abs(double(s.shadow[i].y) - double(truth[i]));
        r.all.add(c, filteredError);
        const int cascade = s.cascade(i);
        if (cascade >= 0 && cascade < cascadeCount) r.cascades[std::size_t(cascade)].add(c, filteredError);
        if (cascade < 0) r.beyond.add(c, filteredError);
    }
    return r;
}

}  // namespace st::metrics
