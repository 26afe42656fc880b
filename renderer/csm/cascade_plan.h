#pragma once
// Everything the frame needs from the cascade math, computed once on the CPU from Settings and
// uploaded (no cascade math in shaders). Also what tests and metrics use to reason about a frame.
#include "renderer/csm/frustum.h"
#include "renderer/csm/light_fit.h"
#include "renderer/csm/storage_layout.h"
#include "renderer/settings/settings.h"

#include <vector>

namespace st::csm {

struct CascadePlan {
    CameraParams camera;
    glm::mat4 vsView{1.0f};
    glm::mat4 csProj{1.0f};
    glm::vec3 wsLightDir{0.0f, -1.0f, 0.0f};  // direction the light travels
    std::vector<float> splits;                // count + 1 view depths
    std::vector<CascadeFit> cascades;
    StorageLayout storage;                    // where each cascade's map lives (cascades.storage)
};

CameraParams cameraFromSettings(const CameraSettings& c, float aspect);

// Throws std::invalid_argument (from the math) for degenerate settings.
CascadePlan planCascades(const Settings& s, float aspect, const Aabb& wsSceneBounds);

}  // namespace st::csm
