#pragma once
// The hover probe over the scene: what the frame on screen did at the pixel under the mouse.
// The app samples the frame (the measurement pass's per-pixel read-back, app/editor/scene_probe.h) and
// fills a ProbeView; the UI shows it next to the mouse and says which pixel it wants next.
#include "ui/layout.h"

namespace st::ui {

struct UiFrame;

struct ProbeView {
    bool valid = false;           // a surface under the mouse, sampled from the frame on screen
    int x = 0, y = 0;             // scene pixel, from the viewport's top left
    int cascade = -1;             // -1: beyond the shadow distance, drawn lit
    float texelWorldSize = 0.0f;  // metres per texel of that cascade
    float pixelsPerTexel = 0.0f;  // screen pixels one shadow texel covers there
    float hardResult = 1.0f;      // the unfiltered test: 1 lit, 0 shadowed
    float filteredFactor = 1.0f;  // what the image shows (filter, blend band)
    float nDotL = 0.0f;           // of the shading normal
    bool sunFacing = false;       // N.L > 0: the shadow test shows there
    float constantBias = 0.0f;    // metres along the light
    float slopeBias = 0.0f;       // metres along the light (slope x texel x tan of the angle)
    float normalOffset = 0.0f;    // metres along the normal
    bool offsetOnCasters = false; // bias.normalOffsetSide caster-sin: casters moved in, x sin(N, L)
    int truth = -1;               // ray-cast ground truth: 1 lit, 0 shadowed, -1 not computed
};

// While the mouse is over the scene viewport and no window: the tooltip, and the pixel asked
// for in UiRequests (probeWanted, probePixel).
void drawProbe(UiFrame& f);

// Where a tooltip of `size` goes for the mouse at `mouse` (display pixels): right of and below
// the cursor as ImGui puts it, else left of or above it, so it stays inside `scene` and off the
// panels around it; where neither side has room, as far as the viewport allows.
ImVec2 placeProbeTooltip(ImVec2 mouse, ImVec2 size, const Rect& scene);

// The width the tooltip's lines wrap at: the viewport's (less the padding), at most 36 em.
float probeWrapWidth(const Rect& scene);

}  // namespace st::ui
