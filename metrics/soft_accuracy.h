#pragma once
// The filtered result against the soft truth (docs/architecture.md#artifact-classes): the
// filtered error, and each receiver's artifact class, judged on the filtered shadow factor f
// (samples.shadow.y) against the visible fraction t of the sun's disc (SoftTruth::visible):
// - correct: |f - t| <= tolerance;
// - acne: too dark (f < t - tolerance) where the truth is fully lit and more than k texels
//   from any true shadow;
// - light bleeding: too light inside a true umbra (t = 0), more than k texels from its edge;
// - peter-panning: too light in true shadow (t < 1) whose caster is within k texels of the
//   receiver along the centre ray: next to a contact, where a caster meets its receiver, which
//   is where depth bias detaches the shadow;
// - missing caster: too light over (nearly) a whole true shadow: a connected region of t < 0.5
//   of which at least missingShare of the pixels are too light;
// - edge: any other error, within k texels of a true edge or in the penumbra itself: the map's
//   resolution and the kernel's width, not a bug.
// Texels are the pixel's cascade's: k texels are k * sqrt(px per texel) screen pixels across
// and k * texelWorldSize metres along the ray. Denominators are the receivers, as accuracy.h.
#include "metrics/ground_truth.h"
#include "renderer/render/measure_samples.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st::metrics {

enum class ArtifactClass : std::uint8_t { NotScored, Correct, Edge, Acne, LightBleeding, PeterPanning, MissingCaster };

struct ArtifactCounts {
    std::size_t receivers = 0;
    std::size_t edge = 0, acne = 0, lightBleeding = 0, peterPanning = 0, missingCaster = 0;
    double filteredAbsErrorSum = 0.0;  // sum of |f - t|

    void add(ArtifactClass c, double absError);
    double share(std::size_t count) const { return receivers ? double(count) / double(receivers) : 0.0; }
    double filteredError() const { return receivers ? filteredAbsErrorSum / double(receivers) : 0.0; }
    std::size_t artifacts() const { return acne + lightBleeding + peterPanning + missingCaster; }
};

// Mean penumbra width in screen pixels: the pixels strictly between umbra and full light over
// the length of the 0.5 contour (pixels >= 0.5 with a 4-neighbour < 0.5), for the truth and for
// the filtered factor (leaving out pixels classed acne, bleeding or missing caster, and greys
// more than k texels out in full light: speckle, not a penumbra). 0 where there is no contour.
struct PenumbraWidth {
    double truthPx = 0.0, filteredPx = 0.0;
    std::size_t truthPixels = 0, truthContour = 0, filteredPixels = 0, filteredContour = 0;
    double errorPx() const { return filteredPx - truthPx; }
};

struct ArtifactParams {
    float k = 2.0f;               // texels (measure.artifactTexels)
    float tolerance = 0.25f;      // |f - t| beyond it is an error: a quarter of the sun's light
    float missingShare = 0.9f;    // of a true shadow's pixels too light for a missing caster
};

struct SoftAccuracyReport {
    ArtifactCounts all;
    std::vector<ArtifactCounts> cascades;  // by the cascade the pixel selected
    PenumbraWidth penumbra;
    std::vector<ArtifactClass> classes;    // per pixel, for artifacts.png
};

// What the scoring reads of the truth and the frame's surfaces alone, not of the shadow result:
// the same for every candidate on one view, so a tune finds it once per view
// (MeasureSession::CachedTruth) instead of at each measurement.
struct SoftTruthRegions {
    std::vector<float> toShadow;  // px from each pixel to the nearest not fully lit one
    std::vector<float> toLight;   // px from each pixel to the nearest not fully shadowed one
    std::vector<int> label;       // 4-connected region of true shadow (t < 0.5), -1 elsewhere
    std::vector<std::size_t> regionSize;
    PenumbraWidth truthPenumbra;  // its truth* fields
};
SoftTruthRegions softTruthRegions(const MeasureSamples& samples, const SoftTruth& truth);

// texelWorldSize[c]: cascade c's texel in metres (CascadeFit::texelWorldSize).
SoftAccuracyReport scoreSoftAccuracy(const MeasureSamples& samples, const SoftTruth& truth,
                                     const std::vector<float>& texelWorldSize, const ArtifactParams& params = {});
// The same with `regions` = softTruthRegions(samples, truth), found earlier.
SoftAccuracyReport scoreSoftAccuracy(const MeasureSamples& samples, const SoftTruth& truth, const SoftTruthRegions& regions,
                                     const std::vector<float>& texelWorldSize, const ArtifactParams& params = {});

// Mean penumbra width of one per-pixel factor over the receivers where `use` is set (empty: all):
// pixels with eps < factor < 1 - eps over the 0.5 contour. The truth's fractions are exact
// multiples of 1 / rays (eps 0); the filtered factor is a float off the GPU (eps 0.02).
void penumbraWidth(const MeasureSamples& s, const std::vector<float>& factor, const std::vector<std::uint8_t>& use,
                   float eps, double& widthPx, std::size_t& pixels, std::size_t& contour);

// Screen distance in pixels from each pixel to the nearest pixel with `source` set (chamfer
// 3-4 distance over the 8-neighbourhood, within 8 % of Euclidean); large where there is none.
std::vector<float> distanceToNearest(int width, int height, const std::vector<std::uint8_t>& source);

}  // namespace st::metrics
