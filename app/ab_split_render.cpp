#include "app/ab_split_render.h"

#include <algorithm>
#include <cmath>

namespace st::app {

Settings aOnLive(const Settings& a, const Settings& live) {
    Settings s = a;
    s.scene = live.scene;
    s.ground = live.ground;
    s.camera = live.camera;
    s.light = live.light;
    s.output = live.output;
    s.path = live.path;
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
