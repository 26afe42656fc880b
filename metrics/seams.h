#pragma once
// Cascade seams: how much the filtered shadow factor jumps where one cascade hands over to the
// next. A seam pair is two 4-neighbour receivers (inside the shadow range) that selected different
// cascades, have the same ground truth and lie on one plane (so a true shadow edge or a step from
// one surface to another is not counted: whatever changes between them is the map's doing); the seam band is
// every pixel within `radius` pixels (Chebyshev) of a seam pair. Figures: the mean
// |filtered(p) - filtered(q)| over the seam pairs (the jump across the split), and the mean
// |filtered - truth| over the receivers of the band. A blend band (cascades.blendBand) fades one
// cascade into the next before the split, so at the split both sides read the same cascade and
// the jump is only what the image itself changes over one pixel.
#include "renderer/render/measure_samples.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st::metrics {

struct SeamReport {
    std::size_t bandPixels = 0;      // receivers in the band
    std::size_t pairs = 0;           // seam pairs the jump is averaged over
    double meanAbsError = 0.0;       // mean |filtered - truth| in the band
    double meanAbsJump = 0.0;        // mean |filtered(p) - filtered(q)| over the seam pairs
};

// The pixels of seam pairs, grown by `radius` pixels.
std::vector<std::uint8_t> seamBand(const MeasureSamples& samples, const std::vector<std::uint8_t>& truth, int radius);

// `truth`: 1 lit, 0 shadowed per pixel (GroundTruth::trace).
SeamReport measureSeams(const MeasureSamples& samples, const std::vector<std::uint8_t>& truth, int radius = 2);

}  // namespace st::metrics
