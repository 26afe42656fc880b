#pragma once
// Where the side view shows each inner split plane, for the handles that drag it: the centre of
// the plane (on the camera's view axis at the split's view depth) projected by the side camera.
#include "renderer/csm/cascade_plan.h"
#include "renderer/render/side_view.h"
#include "ui/split_bar.h"

#include <vector>

namespace st::app {

// One handle per inner split (plan.splits[1..count-1]); a plane behind the side camera gets a
// handle outside the picture (uv < 0), which the panel does not draw. `aspect`: the picture's.
std::vector<ui::SideSplitHandle> sideSplitHandles(const csm::CascadePlan& plan, const OrbitCamera& orbit, float aspect);

}  // namespace st::app
