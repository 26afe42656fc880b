#pragma once
// The pixels of the editor's A/B split: A's settings rendered on the live scene, camera, light
// and size into a copy of their own, then shown left of the divider over the live frame. Needs
// the GL context current; no window, so a GL test composes it headless.
#include "renderer/render/frame_stats.h"
#include "renderer/render/offscreen_target.h"
#include "renderer/render/renderer.h"
#include "renderer/settings/settings.h"

namespace st::app {

// A's method on the live view: A's cascades, filter, bias and every other setting, with the live
// scene, ground, camera, light, output and path. The light is the live one too: the halves show
// one world, so what differs between them is the shadow method alone (and the ground truth, the
// accuracy figures' reference, is the same for both).
Settings aOnLive(const Settings& a, const Settings& live);

// The first column of the live half for a divider at `fraction` of `width`.
int dividerColumn(int width, float fraction);

class AbSplitRender {
public:
    // Renders `aLive` with `r` and keeps a copy of the image; `r` then holds A's frame (shadow
    // maps, plan) until the next render. Throws like Renderer::render.
    FrameStats renderA(Renderer& r, const Settings& aLive);
    // Copies A's columns [0, dividerColumn) over the framebuffer `dst` (0: the window) at
    // (dstX, dstY), the bottom left of the scene viewport there, which must be A's size.
    void composite(GLuint dst, float fraction, int dstX = 0, int dstY = 0) const;
    const OffscreenTarget& image() const { return image_; }

private:
    OffscreenTarget image_;
};

}  // namespace st::app
