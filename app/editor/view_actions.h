#pragma once
// What the editor's camera actions do to the settings, kept apart from the window so it is
// unit-tested: "frame scene" moves the camera only, and a fly gesture is one undo step
// (issue 13 #4). Pure logic over CameraSettings.
#include "renderer/csm/geometry.h"
#include "renderer/settings/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace st::app {

// frameBounds' position and target, with near and far left as the preset has them: they are
// tuning settings (the cascades follow them). When the framed scene reaches past the far plane
// the camera comes in to half the far plane from the centre (same direction) and the result
// says so ("the scene reaches 5938 m, past the far plane (1500 m) ..."); else "".
std::string frameKeepingClipPlanes(CameraSettings& cam, const csm::Aabb& wsBounds);

// What F frames: the union of the draw items' bounds without those that sprawl (more than 20 times
// the median item's diagonal: a 2 km terrain under a town of 8 m houses, where framing everything
// made the town a speck, issue 39 #8); all of `whole` with fewer than 3 items, nothing sprawling,
// or when the sprawling ones are half the items or more.
csm::Aabb framingBounds(const std::vector<csm::Aabb>& items, const csm::Aabb& whole);

// Turns per-frame camera changes into gestures: from the first frame that moves the camera to
// the first frame with the mouse button released.
class CameraGesture {
public:
    // `before`/`after`: the camera before and after this frame's input; `held`: a fly or pan
    // button is still down. Returns the camera at the start of a gesture that has just ended.
    std::optional<CameraSettings> update(const CameraSettings& before, const CameraSettings& after, bool held);

private:
    std::optional<CameraSettings> start_;
};

}  // namespace st::app
