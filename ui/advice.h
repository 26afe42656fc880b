#pragma once
// What to try next, from the figures on screen: rules that read the frame's cascade figures, the
// Accuracy panel's measured counts and the settings, and name the knobs that move the figure.
// Pure functions, no ImGui: each rule is tested on a preset that triggers it.
#include "renderer/render/frame_stats.h"
#include "renderer/settings/settings.h"
#include "ui/accuracy_view.h"

#include <string>
#include <vector>

namespace st::ui {

struct Advice {
    std::string rule;  // stable id, for tests: "coarse-texel", "acne", "peter-panning"
    std::string text;  // one sentence: the figure, what it means, what to try
};

// A shadow texel wider than this cannot give a lamp post, a person or a car a shadow of its own
// shape (each needs a few texels across): the far terrain looks blurry.
inline constexpr float kCoarseTexelMetres = 1.0f;
// Gross errors (acne, leaks, peter-panning) are rare with sane settings (default.json: under
// 0.1 % of sun-facing pixels); above this share the artifact is visible at a glance.
inline constexpr double kGrossShare = 0.005;

// "cascade 3 texel is 1.7 m: ..." for the coarsest cascade above kCoarseTexelMetres.
std::vector<Advice> adviseFromFigures(const Settings& s, const FrameStats& stats);

// Acne (gross false shadow) and peter-panning (gross false light), from a Done view.
std::vector<Advice> adviseFromAccuracy(const Settings& s, const AccuracyView& accuracy);

}  // namespace st::ui
