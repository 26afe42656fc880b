#include "renderer/render/device.h"

#include "renderer/gpu/gl.h"

namespace st {

DeviceLimits deviceLimits() {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    return {maxSize};
}

std::string deviceRendererName() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "";
}

void finishDeviceWork() { glFinish(); }

}  // namespace st
