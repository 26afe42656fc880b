#include "renderer/render/line_pass.h"

#include "renderer/render/shader_library.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstddef>

namespace st {

LinePass::LinePass() {
    program_ = gpu::linkProgram(shaderSource("lines.vert"), shaderSource("lines.frag"), "lines");
    vao_ = gpu::createVertexArray();
    for (GLuint a = 0; a < 2; ++a) {
        glEnableVertexArrayAttrib(vao_.id(), a);
        glVertexArrayAttribFormat(vao_.id(), a, 3, GL_FLOAT, GL_FALSE,
                                  a == 0 ? offsetof(LineVertex, position) : offsetof(LineVertex, color));
        glVertexArrayAttribBinding(vao_.id(), a, 0);
    }
}

void LinePass::draw(const std::vector<LineVertex>& lines, const glm::mat4& viewProj) {
    if (lines.empty()) return;
    gpu::DebugGroup group("wireframes");
    if (lines.size() > capacity_) {  // grow only; immutable storage is recreated
        capacity_ = lines.size() * 2;
        buffer_ = gpu::createBuffer(nullptr, GLsizeiptr(capacity_ * sizeof(LineVertex)), GL_DYNAMIC_STORAGE_BIT);
        glVertexArrayVertexBuffer(vao_.id(), 0, buffer_.id(), 0, sizeof(LineVertex));
    }
    glNamedBufferSubData(buffer_.id(), 0, GLsizeiptr(lines.size() * sizeof(LineVertex)), lines.data());
    glUseProgram(program_.id());
    glProgramUniformMatrix4fv(program_.id(), glGetUniformLocation(program_.id(), "uViewProj"), 1, GL_FALSE,
                              glm::value_ptr(viewProj));
    glBindVertexArray(vao_.id());
    // Hidden parts dim, visible parts bright: boxes below the ground stay readable.
    GLint brightness = glGetUniformLocation(program_.id(), "uBrightness");
    glDisable(GL_DEPTH_TEST);
    glProgramUniform1f(program_.id(), brightness, 0.35f);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size()));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glProgramUniform1f(program_.id(), brightness, 1.0f);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size()));
    glDepthFunc(GL_LESS);
}

}  // namespace st
