#pragma once
// The one table of cascade tints, linear RGB: the cascades view (CascadeData::tint), the side
// view's wireframes and the editor's colour keys all read it. Plain values, no GL, so ui/ can
// include it. Eight entries; cascade i uses entry i % 8. White is not among them: the side view
// draws the camera frustum in it.
#include <array>
#include <cstddef>

namespace st {

struct LinearRgb {
    float r, g, b;
};

inline constexpr std::array<LinearRgb, 8> kCascadeTints{{{1.0f, 0.25f, 0.25f}, {0.25f, 1.0f, 0.25f},
                                                          {0.3f, 0.45f, 1.0f}, {1.0f, 1.0f, 0.2f},
                                                          {1.0f, 0.3f, 1.0f}, {0.2f, 1.0f, 1.0f},
                                                          {1.0f, 0.6f, 0.1f}, {0.6f, 0.3f, 1.0f}}};

constexpr LinearRgb cascadeTintOf(int cascade) {
    return kCascadeTints[static_cast<std::size_t>(cascade < 0 ? 0 : cascade) % kCascadeTints.size()];
}

}  // namespace st
