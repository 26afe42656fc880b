#pragma once
// Debug wireframes (GL_LINES) and point clouds (GL_POINTS) drawn over a target that already holds
// the scene's depth.
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
    // Into `framebuffer` (width x height), depth-tested against what it holds: parts behind the
    // scene dimmed, visible parts bright.
    void draw(const std::vector<LineVertex>& lines, const glm::mat4& viewProj, GLuint framebuffer, int width,
              int height);
    // 2-pixel points lying on the scene's surfaces (texel_cloud.h): pulled toward the viewer so
    // they win the depth test against the surface they sit on; hidden ones are not drawn.
    void drawPoints(const std::vector<LineVertex>& points, const glm::mat4& viewProj, GLuint framebuffer, int width,
                    int height);

private:
    void upload(const std::vector<LineVertex>& vertices, const glm::mat4& viewProj);
    gpu::Program program_;
    gpu::Program pointProgram_;
    gpu::VertexArray vao_;
    gpu::Buffer buffer_;
    std::size_t capacity_ = 0;  // vertices
    gpu::UniformBuffer<gpu_if::ViewBlock> view_;
    gpu::UniformBuffer<gpu_if::OverlayBlock> hidden_;   // brightness of the parts behind the scene
    gpu::UniformBuffer<gpu_if::OverlayBlock> visible_;
};

}  // namespace st
