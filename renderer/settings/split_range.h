#pragma once
// Where the cascades end: the shadow distance when one is set (seed 001), else the camera's far
// plane. A reading of the settings, header-only (part of st_settings_types) so validation, the
// UI and the cascade math (computeSplits) share it.
#include "renderer/settings/settings.h"

namespace st {

inline float splitRangeEnd(float farPlane, float shadowDistance) {
    return shadowDistance > 0.0f ? shadowDistance : farPlane;
}

inline float splitRangeEnd(const CameraSettings& camera, const CascadeSettings& cascades) {
    return splitRangeEnd(camera.farPlane, cascades.shadowDistance);
}

}  // namespace st
