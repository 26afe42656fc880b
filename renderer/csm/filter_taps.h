#pragma once
// How many shadow-map reads one shaded fragment's filter takes, derived from the settings the way
// shaders/shadow_sampling.glsl's sampleCascade spends them (the counters' filterTaps and
// bytesRead, renderer/render/pass_work.h). A count of one cascade's filter at its nominal size:
// - a fragment in a blend band samples two cascades (twice this), one beyond the shadow range
//   none, and PCSS skips its filter taps where the blocker search finds nothing; none of these
//   data-dependent cases is counted, so the figure is the same for the same settings;
// - a "tap" is one texture instruction; a bilinear (2x2 compare or linear) tap reads 4 texels, a
//   trilinear one 8, a nearest or raw one 1.
#include "renderer/settings/settings.h"

namespace st::csm {

struct FilterTaps {
    int taps = 0;           // texture instructions per shaded fragment
    int texels = 0;         // texels those read
    int bytesPerTexel = 0;  // of the map they read: 4 (D32F depth) or the moment format's
};

// Of the filter the main pass (or the screen-space mask) applies per fragment.
FilterTaps filterTapsPerFragment(const FilterSettings& f, bool receiverPlane);

// Bytes per texel of a moment filter's array (RG32F/RG16F, RGBA32F/RGBA16F, RGBA16 for 16-bit MSM);
// 0 for a kind without moments.
int momentBytesPerTexel(FilterKind kind, bool sixteenBit);

}  // namespace st::csm
