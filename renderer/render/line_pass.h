#pragma once
// Debug wireframes (GL_LINES) drawn over a target that already holds the scene's depth.
#include "renderer/gpu/gl.h"
#include "renderer/gpu/uniform_buffer.h"
#include "renderer/render/side_view.h"
#include "shaders/interface.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace st {

class LinePass {
public:
    LinePass();
    // Into `framebuffer` (width x height), depth-tested against what it holds.
    void draw(const std::vector<LineVertex>& lines, const glm::mat4& viewProj, GLuint framebuffer, int width,
              int height);

private:
    gpu::Program program_;
    gpu::VertexArray vao_;
    gpu::Buffer buffer_;
    std::size_t capacity_ = 0;  // vertices
    gpu::UniformBuffer<gpu_if::ViewBlock> view_;
    gpu::UniformBuffer<gpu_if::OverlayBlock> hidden_;   // brightness of the parts behind the scene
    gpu::UniformBuffer<gpu_if::OverlayBlock> visible_;
};

}  // namespace st
