#include "app/ab_split_render.h"

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
    glBlitNamedFramebuffer(r.framebuffer(), image_.framebuffer(), 0, 0, r.width(), r.height(), 0, 0, r.width(),
                           r.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return stats;
}

void AbSplitRender::composite(GLuint dst, float fraction, int dstX, int dstY) const {
    const int x = dividerColumn(image_.width(), fraction);
    if (x <= 0) return;
    glBlitNamedFramebuffer(image_.framebuffer(), dst, 0, 0, x, image_.height(), dstX, dstY, dstX + x, dstY + image_.height(),
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

}  // namespace st::app
