#pragma once
// The images beside metrics.json, one colour per meaning (top row first, RGBA8).
#include "metrics/accuracy.h"
#include "metrics/soft_accuracy.h"
#include "renderer/image/image_io.h"
#include "renderer/render/measure_samples.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace st::metrics {

// Ground truth: lit white, shadowed dark grey, facing away from the sun darker blue-grey,
// no surface slate.
Rgba8Image truthImage(const MeasureSamples& s, const std::vector<std::uint8_t>& truth);

// Errors of the unfiltered test: false shadow (acne) in magentas, false light (leaks, missing
// casters) in blues; pale inside the edge band (expected aliasing), saturated outside it (gross).
// Correct pixels in greys (lit light, shadow mid), facing away dark, the terminator band of
// smooth meshes dark purple, no surface slate.
Rgba8Image errorImage(const AccuracyReport& a, int width, int height);

// The same errors for drawing over the scene: false shadow in magentas, false light in cyans, opaque;
// lighter in the edge band, saturated when gross, and gross pixels ringed by a translucent halo
// of their colour so a lone one can be found in a full-window view. Everything else is fully
// transparent. Straight alpha.
Rgba8Image errorOverlayImage(const AccuracyReport& a, int width, int height);

// One colour of an image and what it means, with the pixels of that colour.
struct LegendEntry {
    std::string name;
    std::array<std::uint8_t, 3> colour{};
    std::size_t pixels = 0;
};

// errorImage's colours, in its order (every colour it uses is one of them).
std::vector<LegendEntry> errorLegend(const AccuracyReport& a);

// The artifact classes of the filtered result against the soft truth: acne red, light bleeding
// orange, peter-panning magenta, missing caster blue, edge error pale yellow; correct pixels in
// greys by their true light (lit light, penumbra mid, umbra dark), not scored (facing away,
// terminator, no surface) slate.
Rgba8Image artifactImage(const MeasureSamples& s, const SoftTruth& truth, const SoftAccuracyReport& r);
std::vector<LegendEntry> artifactLegend(const SoftTruth& truth, const SoftAccuracyReport& r);

// Screen pixels per texel on log2, the texel-density view's ramp: blue (1/16) .. green (1) ..
// red (16); grey beyond the shadow range.
Rgba8Image densityImage(const MeasureSamples& s);

// Per-pixel temporal standard deviation of the hard result along the path: dark grey (steady)
// to yellow (0.5: as often lit as shadowed).
Rgba8Image flickerImage(const std::vector<float>& stdDev, const MeasureSamples& s);

}  // namespace st::metrics
