#pragma once
// Synthetic MeasureSamples for tests that need no GL: a flat, sun-facing floor by default.
#include "renderer/render/measure_samples.h"

namespace st::test {

// width x height receivers on y = 0 (x = column, z = row, metres), shading and geometric
// normal +Y with N.L = 1, lit by
// the map (hard = filtered = 1), in cascade 0, one screen pixel per texel.
MeasureSamples floorSamples(int width, int height);

// Sets pixel (x, y)'s map result: hard and filtered factor.
void setMap(MeasureSamples& s, int x, int y, float hard, float filtered);

}  // namespace st::test
