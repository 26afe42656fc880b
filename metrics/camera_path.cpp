#include "metrics/camera_path.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace st::metrics {

CameraSettings cameraOnPath(const Settings& s, int frame) {
    const auto& keys = s.path.keyframes;
    if (keys.empty()) throw std::invalid_argument("path.keyframes: a path needs at least one keyframe");
    const int segments = int(keys.size()) - 1;
    const int steps = std::max(s.path.frames - 1, 1);
    // Position along the keyframes in units of segments, computed in double so the last frame
    // lands exactly on the last keyframe.
    const double t = double(std::clamp(frame, 0, steps)) * double(segments) / double(steps);
    const int k = std::min(int(std::floor(t)), std::max(segments - 1, 0));
    const float f = segments > 0 ? float(t - double(k)) : 0.0f;
    const CameraKeyframe& a = keys[std::size_t(k)];
    const CameraKeyframe& b = keys[std::size_t(std::min(k + 1, segments))];
    CameraSettings c = s.camera;
    c.position = glm::mix(a.position, b.position, f);
    c.target = glm::mix(a.target, b.target, f);
    c.fovY = glm::mix(a.fovY, b.fovY, f);
    return c;
}

Settings atPathFrame(const Settings& s, int frame) {
    Settings out = s;
    out.camera = cameraOnPath(s, frame);
    return out;
}

}  // namespace st::metrics
