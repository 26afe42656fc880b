#pragma once
// Slice corners found the way an engine that keeps its matrices in float32 finds them.
#include "renderer/csm/frustum.h"

#include <glm/vec3.hpp>

namespace st::csm {

// The camera exactly as the engine was given it (double: the job's numbers, not rounded again).
struct Float32Camera {
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    double fovYDegrees = 60.0;  // vertical
    double aspect = 16.0 / 9.0;
    double nearPlane = 0.1;
    double farPlane = 400.0;
};

// Babylon.js 9.28 (cascadedShadowGenerator.pure.js _computeFrustumInWorldSpace:423-459; its reference,
// engines/babylon/test/reference.mjs sliceCorners): the camera's view and projection stored as
// float32, their product stored as float32, inverted with cofactors in double and stored as float32,
// the NDC cube's corners unprojected through it in double, each near->far edge cut at the break
// fractions b0, b1 of [near, far]. Mathematically sliceCornersFromCamera; numerically the float32
// inverse moves far corners by up to ~1e-4 of their distance when far/near is in the thousands, a
// tenth of a texel at the edge of a 2048 map: the acne stripes show it (docs/engines.md).
// Order as Corners: near (-,-) (+,-) (+,+) (-,+), then far.
Corners sliceCornersThroughFloat32Inverse(const Float32Camera& cam, double b0, double b1);

}  // namespace st::csm
