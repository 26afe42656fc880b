#pragma once
// The fixed-function state a pass draws with, set in full when the pass starts (after Fwog's
// pipeline objects): no pass relies on what the previous one left behind, so passes can run in
// any order (tests/render/pass_order_gl_test.cpp).
#include "renderer/gpu/gl.h"

#include <glm/vec4.hpp>

namespace st::gpu {

struct PassState {
    GLuint framebuffer = 0;
    glm::ivec4 viewport{0, 0, 0, 0};  // x, y, width, height
    bool depthTest = false;
    bool depthWrite = false;
    GLenum depthFunc = GL_LESS;
    GLenum cullFace = GL_NONE;  // GL_BACK or GL_FRONT culls; GL_NONE disables culling
    bool depthClamp = false;    // pancaking: casters in front of the near plane clamp onto it
    float polygonOffsetFactor = 0.0f;  // both 0: polygon offset disabled
    float polygonOffsetUnits = 0.0f;
    bool blend = false;         // premultiplied-style src alpha over
    bool colorWrite = true;
    bool scissor = false;
    glm::ivec4 scissorBox{0, 0, 0, 0};
};

void applyPassState(const PassState& state);

// Drawing the scene into `framebuffer` (width x height): depth-tested, back faces culled (the
// draws turn culling off for double-sided materials). The main and the measurement pass share
// it, so the metrics score the pixels the image shows.
PassState opaqueScenePass(GLuint framebuffer, int width, int height);

}  // namespace st::gpu
