#include "renderer/render/line_pass.h"

#include "renderer/gpu/pass_state.h"
#include "renderer/render/shader_library.h"

#include <cstddef>

namespace st {

LinePass::LinePass() {
    program_ = linkShaderFiles("lines.vert", "lines.frag", "lines");
    pointProgram_ = linkShaderFiles("texel_points.vert", "lines.frag", "texel points");
    vao_ = gpu::createVertexArray();
    const GLuint locations[2] = {ST_ATTRIB_POSITION, ST_ATTRIB_COLOR};
    const GLuint offsets[2] = {offsetof(LineVertex, position), offsetof(LineVertex, color)};
    for (int i = 0; i < 2; ++i) {
        glEnableVertexArrayAttrib(vao_.id(), locations[i]);
        glVertexArrayAttribFormat(vao_.id(), locations[i], 3, GL_FLOAT, GL_FALSE, offsets[i]);
        glVertexArrayAttribBinding(vao_.id(), locations[i], 0);
    }
    gpu_if::OverlayBlock dim, bright;
    dim.brightness = 0.35f;
    bright.brightness = 1.0f;
    hidden_.upload(dim);
    visible_.upload(bright);
}

void LinePass::upload(const std::vector<LineVertex>& vertices, const glm::mat4& viewProj) {
    if (vertices.size() > capacity_) {  // grow only; immutable storage is recreated
        capacity_ = vertices.size() * 2;
        buffer_ = gpu::createBuffer(nullptr, GLsizeiptr(capacity_ * sizeof(LineVertex)), GL_DYNAMIC_STORAGE_BIT);
        glVertexArrayVertexBuffer(vao_.id(), 0, buffer_.id(), 0, sizeof(LineVertex));
    }
    glNamedBufferSubData(buffer_.id(), 0, GLsizeiptr(vertices.size() * sizeof(LineVertex)), vertices.data());
    view_.upload({viewProj});
    view_.bind(ST_BLOCK_VIEW);
    glBindVertexArray(vao_.id());
}

void LinePass::draw(const std::vector<LineVertex>& lines, const glm::mat4& viewProj, GLuint framebuffer, int width,
                    int height) {
    if (lines.empty()) return;
    gpu::DebugGroup group("wireframes");
    upload(lines, viewProj);
    glUseProgram(program_.id());
    // Hidden parts dim, visible parts bright: boxes below the ground stay readable.
    gpu::PassState state;
    state.framebuffer = framebuffer;
    state.viewport = {0, 0, width, height};
    gpu::applyPassState(state);
    hidden_.bind(ST_BLOCK_OVERLAY);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size()));
    state.depthTest = true;
    state.depthFunc = GL_LEQUAL;
    gpu::applyPassState(state);
    visible_.bind(ST_BLOCK_OVERLAY);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size()));
}

void LinePass::drawPoints(const std::vector<LineVertex>& points, const glm::mat4& viewProj, GLuint framebuffer,
                          int width, int height) {
    if (points.empty()) return;
    gpu::DebugGroup group("points");
    upload(points, viewProj);
    glUseProgram(pointProgram_.id());
    gpu::PassState state;
    state.framebuffer = framebuffer;
    state.viewport = {0, 0, width, height};
    state.depthTest = true;
    state.depthFunc = GL_LEQUAL;
    gpu::applyPassState(state);
    visible_.bind(ST_BLOCK_OVERLAY);
    glPointSize(2.0f);
    glDrawArrays(GL_POINTS, 0, GLsizei(points.size()));
    glPointSize(1.0f);
}

}  // namespace st
