#include "renderer/csm/filter_taps.h"

namespace st::csm {

int momentBytesPerTexel(FilterKind kind, bool sixteenBit) {
    switch (kind) {
        case FilterKind::Vsm:
        case FilterKind::Evsm2: return sixteenBit ? 4 : 8;
        case FilterKind::Evsm4:
        case FilterKind::Msm: return sixteenBit ? 8 : 16;
        default: return 0;
    }
}

FilterTaps filterTapsPerFragment(const FilterSettings& f, bool receiverPlane) {
    constexpr int kDepthBytes = 4;  // D32F
    // A bilinear compare is one instruction over 4 texels; receiver-plane bias turns it into four
    // nearest compares, each against its own texel's depth (pcf2x2 in shadow_sampling.glsl).
    const int perBilinear = receiverPlane ? 4 : 1;
    const int n2 = f.size * f.size;
    switch (f.kind) {
        case FilterKind::Hard: return {1, 1, kDepthBytes};
        case FilterKind::Pcf2x2: return {perBilinear, 4, kDepthBytes};
        case FilterKind::PcfNxN: return {n2 * perBilinear, 4 * n2, kDepthBytes};
        case FilterKind::Vogel: return {f.vogelTaps * perBilinear, 4 * f.vogelTaps, kDepthBytes};
        case FilterKind::Tent: {
            const int taps = f.size <= 3 ? 4 : 9;  // pcfTent in shadow_sampling.glsl
            return {taps * perBilinear, 4 * taps, kDepthBytes};
        }
        case FilterKind::Pcss: {
            const int blockers = f.blockerTaps * f.blockerTaps;  // raw reads, one texel each
            return {blockers + n2 * perBilinear, blockers + 4 * n2, kDepthBytes};
        }
        case FilterKind::Vsm:
        case FilterKind::Evsm2:
        case FilterKind::Evsm4:
        case FilterKind::Msm: return {1, f.mipmaps ? 8 : 4, momentBytesPerTexel(f.kind, f.moments16)};
    }
    return {};
}

}  // namespace st::csm
