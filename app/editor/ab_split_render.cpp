#include "app/editor/ab_split_render.h"

#include "renderer/render/present.h"
#include "renderer/settings/method_on_view.h"

#include <algorithm>
#include <cmath>

namespace st::app {

Settings aOnLive(const Settings& a, const Settings& live) {
    Settings s = methodOnView(a, live);
    s.output = live.output;  // the split's halves are one image: the live size
    return s;
}

int dividerColumn(int width, float fraction) {
    return std::clamp(int(std::lround(double(fraction) * width)), 0, width);
}

FrameStats AbSplitRender::renderA(Renderer& r, const Settings& aLive) {
    const FrameStats stats = r.render(aLive);
    image_.ensure(r.width(), r.height());
    const PixelRect frame{0, 0, r.width(), r.height()};
    blitColor(r.framebuffer(), frame, image_.framebuffer(), frame);
    return stats;
}

void AbSplitRender::composite(GLuint dst, float fraction, int dstX, int dstY) const {
    const int x = dividerColumn(image_.width(), fraction);
    if (x <= 0) return;
    blitColor(image_.framebuffer(), {0, 0, x, image_.height()}, dst, {dstX, dstY, x, image_.height()});
}

}  // namespace st::app
