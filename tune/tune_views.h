#pragma once
// The views a tune scores settings on (docs/tuning.md#views): the preset's camera, then
// deterministic viewpoints around it, some held out. A tune that fits only the views it saw shows
// as a gap between its tuned and held-out figures. No GL.
#include "renderer/settings/settings.h"

#include <string>
#include <vector>

namespace st::tune {

struct View {
    std::string name;  // "preset camera", "orbit +12 deg, up 15 %", ...
    CameraSettings camera;
    bool heldOut = false;
};

// `count` views (>= 1): the preset's camera, then cameras orbiting its target by alternating
// +-12, +-24, ... degrees about the vertical, alternately raised and lowered by 15 % of the
// camera's height over the target. Counting the preset camera as view 1, views k, 2k, ... are
// held out (`holdOutEvery` = k; 0: none; the preset camera never is). With a camera path of keyframes the path's poses come first after the camera.
std::vector<View> tuneViews(const Settings& s, int count, int holdOutEvery);

// `s` seen from `v` (the cascades follow the view's camera; the path is dropped: a tune scores
// still frames and measures flicker separately on the preset's own camera).
Settings onView(Settings s, const View& v);

}  // namespace st::tune
