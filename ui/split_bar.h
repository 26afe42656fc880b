#pragma once
// The cascade split bar under the scene (as Unity's and Godot's cascade editors): each cascade's
// view-depth range in metres and in percent of the shadow distance, with a handle on every inner
// split. Dragging a handle switches the scheme to manual, starting from the splits on screen, and
// is one undo step (one widget gesture).
#include "renderer/settings/settings.h"

#include <imgui.h>

#include <vector>

namespace st::ui {

// The inner splits the bar shows and edits: the manual splits while the scheme is manual and
// they match the count (they lead the rendered figures by a frame while dragging), else the
// rendered frame's splits[1..count-1]. `rendered` is FrameStats::splits (count + 1 depths).
std::vector<float> innerSplits(const Settings& s, const std::vector<float>& rendered);

// A split plane's handle in the side view's picture, from the app's side camera: where the plane's
// centre is (0..1 of the picture, top left origin) and how it moves per metre of split depth.
struct SideSplitHandle {
    ImVec2 uv{0.0f, 0.0f};
    ImVec2 uvPerMetre{0.0f, 0.0f};
};

// `depth` for inner split `index`, kept between its neighbours (and the bar's ends) so the manual
// splits stay increasing and no cascade is thinner than 1 % of the range or 0.5 m.
float clampedSplit(const std::vector<float>& inner, int index, float nearDepth, float farDepth, float depth);

// The depth a handle dragged to `fraction` (0 at the near end of the bar, 1 at the shadow
// distance, linear in view depth) stands for, kept strictly between its neighbours so the
// manual splits stay increasing. `inner`: the current inner splits; `index` into it.
float draggedSplit(const std::vector<float>& inner, int index, float nearDepth, float farDepth, float fraction);

struct UiFrame;
// Switches to the manual scheme with `inner` as its splits, through the field table (f.edited).
void storeManualSplits(UiFrame& f, const std::vector<float>& inner);

}  // namespace st::ui
