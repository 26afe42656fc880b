#pragma once
// Where the cascades end: the shadow distance when one is set (seed 001), else the camera's far
// plane. Header-only so validation (st_settings) and the UI share it with computeSplits.
#include "renderer/settings/settings.h"

namespace st::csm {

inline float splitRangeEnd(float farPlane, float shadowDistance) {
    return shadowDistance > 0.0f ? shadowDistance : farPlane;
}

inline float splitRangeEnd(const CameraSettings& camera, const CascadeSettings& cascades) {
    return splitRangeEnd(camera.farPlane, cascades.shadowDistance);
}

}  // namespace st::csm
