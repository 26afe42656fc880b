#include "renderer/gpu/pass_state.h"

namespace st::gpu {
namespace {
void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }
}  // namespace

void applyPassState(const PassState& s) {
    glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
    glViewport(s.viewport.x, s.viewport.y, s.viewport.z, s.viewport.w);
    enable(GL_DEPTH_TEST, s.depthTest);
    glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
    glDepthFunc(s.depthFunc);
    enable(GL_CULL_FACE, s.cullFace != GL_NONE);
    if (s.cullFace != GL_NONE) glCullFace(s.cullFace);
    glFrontFace(GL_CCW);
    enable(GL_DEPTH_CLAMP, s.depthClamp);
    const bool offset = s.polygonOffsetFactor != 0.0f || s.polygonOffsetUnits != 0.0f;
    enable(GL_POLYGON_OFFSET_FILL, offset);
    glPolygonOffset(s.polygonOffsetFactor, s.polygonOffsetUnits);
    enable(GL_BLEND, s.blend);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    const GLboolean c = s.colorWrite ? GL_TRUE : GL_FALSE;
    glColorMask(c, c, c, c);
    enable(GL_SCISSOR_TEST, s.scissor);
    glScissor(s.scissorBox.x, s.scissorBox.y, s.scissorBox.z, s.scissorBox.w);
    enable(GL_STENCIL_TEST, false);
    enable(GL_FRAMEBUFFER_SRGB, false);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

PassState opaqueScenePass(GLuint framebuffer, int width, int height) {
    PassState state;
    state.framebuffer = framebuffer;
    state.viewport = {0, 0, width, height};
    state.depthTest = state.depthWrite = true;
    state.cullFace = GL_BACK;
    return state;
}

}  // namespace st::gpu
