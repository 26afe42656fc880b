#pragma once
// Sample distribution shadow maps (Lauritzen, Salvi, Lefohn 2011, "Sample Distribution Shadow
// Maps", SDSM): what a reduction of the camera's depth buffer gives, and how the cascades use it.
// The reduction itself runs on the GPU (renderer/render/depth_bounds_pass.h); this is the pure
// part: the range the splits are placed in and the box a cascade is fitted to.
#include "renderer/csm/geometry.h"

#include <optional>
#include <vector>

namespace st::csm {

// Nearest and farthest view depth of the pixels the camera sees (background excluded).
struct DepthRange {
    float vsMin = 0.0f;
    float vsMax = 0.0f;
    bool operator==(const DepthRange&) const = default;
};

// What the reduction of one frame gives. `depth` is nullopt when no pixel shows geometry;
// lsCascade[i] (light view space, see conventions.h) is nullopt when cascade i holds no sample.
struct SampleBounds {
    std::optional<DepthRange> depth;
    std::vector<std::optional<Aabb>> lsCascade;
};

struct SplitRange {
    float begin = 0.0f;
    float end = 0.0f;
};

// The view-depth range the split scheme divides (SDSM section 3.1: the scheme is unchanged, only
// its range tightens): [nearPlane, end] when nothing is seen, else the seen range clamped into
// it and widened by a relative 1e-4 so a pixel on the farthest depth still falls inside after
// the float round trip. Never shorter than 1e-3 of its start (a wall facing the camera is seen
// at one depth; the scheme needs begin < end). If everything seen lies beyond `end`, nothing is
// shadowed and [nearPlane, end] is kept.
SplitRange fittedSplitRange(float nearPlane, float end, const std::optional<DepthRange>& seen);

}  // namespace st::csm
