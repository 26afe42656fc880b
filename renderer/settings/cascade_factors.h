#pragma once
// The per-cascade lists (bias.constantScale, slopeScale, normalOffsetScale; cascades.mapSizes) kept
// valid when the field they depend on changes: the editor's widgets, its applied tune changes and
// the tuner's moves call keepCascadeListsValid, so no such change leaves a list validation refuses.
#include "renderer/settings/settings.h"

#include <cstddef>
#include <string_view>
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

// After the field at `path` changed: the lists follow cascades.count, and a move to the array
// storage (one size for every layer) drops the per-cascade sizes.
inline void keepCascadeListsValid(Settings& s, std::string_view path) {
    if (path == "cascades.count") {
        fitCascadeFactors(s.bias, s.cascades.count);
        fitCascadeMapSizes(s.cascades);
    }
    if (path == "cascades.storage" && s.cascades.storage == CascadeStorage::Array) s.cascades.mapSizes.clear();
}

}  // namespace st
