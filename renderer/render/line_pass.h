#pragma once
// Debug wireframes (GL_LINES) drawn over a target that already holds the scene's depth.
#include "renderer/gpu/gl.h"
#include "renderer/render/side_view.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace st {

class LinePass {
public:
    LinePass();
    void draw(const std::vector<LineVertex>& lines, const glm::mat4& viewProj);

private:
    gpu::Program program_;
    gpu::VertexArray vao_;
    gpu::Buffer buffer_;
    std::size_t capacity_ = 0;  // vertices
};

}  // namespace st
