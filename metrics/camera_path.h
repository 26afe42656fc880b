#pragma once
// The cascade camera along a preset's path (Settings::path): keyframes spread evenly over the
// frames, linear in position, target and fovY between them. Linear, so a two-keyframe path is
// an exact translation when both poses look the same way (the flicker controls rely on that).
#include "renderer/settings/settings.h"

namespace st::metrics {

// The camera at `frame` (0 .. path.frames-1) of s.path; near/far planes stay s.camera's. With a
// single keyframe, every frame is that pose. Requires at least one keyframe.
CameraSettings cameraOnPath(const Settings& s, int frame);

// `s` with its camera moved to the path's frame: the settings the cascades are planned from.
Settings atPathFrame(const Settings& s, int frame);

}  // namespace st::metrics
