#pragma once
// Everything the frame needs from the cascade math, computed once on the CPU from Settings and
// uploaded (no cascade math in shaders). Also what tests and metrics use to reason about a frame.
#include "renderer/csm/depth_bounds.h"
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
    SplitRange splitRange;                    // what the scheme divided: [near, end] or the fitted range
    bool depthFitted = false;                 // splits placed inside the seen range (depthBounds fit)
    std::vector<CascadeFit> cascades;
    StorageLayout storage;                    // where each cascade's map lives (cascades.storage)
};

CameraParams cameraFromSettings(const CameraSettings& c, float aspect);

// The split depths of `s`: by its scheme over [near, end] (end: shadow distance or far plane),
// or with depthBounds "fit" over fittedSplitRange(near, end, seen). Manual splits are fixed
// depths: fit leaves them where they are. `range` receives the range divided.
std::vector<float> planSplits(const Settings& s, const std::optional<DepthRange>& seen, SplitRange* range = nullptr);

// Throws std::invalid_argument (from the math) for degenerate settings. `samples` (the frame's
// reduction) feeds depthBounds "fit" and FitMode::Samples; without it both behave as off/cascade.
CascadePlan planCascades(const Settings& s, float aspect, const Aabb& wsSceneBounds,
                         const SampleBounds* samples = nullptr);

// Whether the frame needs the depth reduction before planning.
bool needsSampleBounds(const CascadeSettings& c);
// Whether the split depths follow the seen depth range (depth bounds fit a computed scheme), so
// the range must be reduced before the cascades' samples can be.
bool splitsFollowSeenDepth(const CascadeSettings& c);

}  // namespace st::csm
