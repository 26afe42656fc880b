#pragma once
// Colour keys for the debug views: which tint is which cascade (the cascades view, the side
// view's wireframes, the per-cascade tables) and the texel-density view's fixed log scale.
#include "ui/layout.h"

#include <imgui.h>

#include <array>

namespace st::ui {

// Cascade `i`'s tint (renderer/render/cascade_tints.h) as the cascades view shows it: the
// linear tint encoded as the shader's encodeSrgb does (shaders/main.frag, gamma 2.2).
ImVec4 cascadeColour(int cascade);

// The texel-density view's colour for `pixelsPerTexel` screen pixels per shadow texel, as
// shaders/main.frag's texelDensityColor (v = log2(ppt) / 4 clamped to [-1, 1]: blue at 1/16,
// green at 1 — Lloyd et al.'s ideal, one pixel per texel — red at 16), before lighting.
ImVec4 texelDensityColour(float pixelsPerTexel);

// The ticks the colour bar labels, in pixels per texel.
inline constexpr std::array<float, 5> kDensityTicks{1.0f / 16.0f, 0.25f, 1.0f, 4.0f, 16.0f};

// A small filled square in cascade i's colour, then "C<i>" (same line); for tables and lists.
void cascadeSwatch(int cascade);
// "Cascades: [] C0 [] C1 ...": one line, for a panel.
void cascadeKey(int count);

// Legends drawn over the scene viewport's corner with the background draw list (under every
// panel, over the scene): the cascade key for the cascades view, the colour bar for the
// texel-density view. Returns the rectangle drawn (tests).
Rect drawCascadeLegend(ImDrawList* list, const Rect& scene, int count);
Rect drawDensityLegend(ImDrawList* list, const Rect& scene);

}  // namespace st::ui
