#pragma once
// The current context's device: its name, the limits a preset must fit, and waiting for the work
// queued on it. Here so that app/ makes no GL calls of its own.
#include <string>

namespace st {

struct DeviceLimits {
    int maxTextureSize = 0;  // GL_MAX_TEXTURE_SIZE: the side of any texture or render target
};

DeviceLimits deviceLimits();

// GL_RENDERER ("llvmpipe (LLVM 15.0.6, 256 bits)"); empty when the context does not say.
std::string deviceRendererName();

// glFinish: returns once every queued command has run, so a wall-clock time covers the GPU work.
void finishDeviceWork();

}  // namespace st
