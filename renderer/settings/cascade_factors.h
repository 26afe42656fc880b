#pragma once
// The per-cascade lists (bias.constantScale, slopeScale, normalOffsetScale; cascades.mapSizes) kept
// valid when cascades.count changes: the editor's count widget and the tuner's count moves call it, so
// a count change never leaves a list that validation refuses.
#include "renderer/settings/settings.h"

#include <cstddef>
#include <vector>

namespace st {

// An empty list stays empty (every cascade at the global bias); a longer one is cut to `count`,
// a shorter one padded with 1 (the global bias for the new cascades).
inline void fitCascadeFactors(BiasSettings& b, int count) {
    const auto n = static_cast<std::size_t>(count < 0 ? 0 : count);
    for (std::vector<float>* list : {&b.constantScale, &b.slopeScale, &b.normalOffsetScale})
        if (!list->empty()) list->resize(n, 1.0f);
}

// Per-cascade map sizes (cascades.mapSizes) likewise: an empty list stays empty (every cascade at
// cascades.mapSize), a longer one is cut, a shorter one padded with its last size.
inline void fitCascadeMapSizes(CascadeSettings& c) {
    if (c.mapSizes.empty() || c.count < 1) return;
    c.mapSizes.resize(static_cast<std::size_t>(c.count), c.mapSizes.back());
}

// Both, after a change of cascades.count (the editor's count widget, the tuner's count moves).
inline void fitCascadeLists(Settings& s) {
    fitCascadeFactors(s.bias, s.cascades.count);
    fitCascadeMapSizes(s.cascades);
}

}  // namespace st
