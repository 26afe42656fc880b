#pragma once
// The GPU side of sample distribution shadow maps (renderer/csm/depth_bounds.h): a compute
// reduction of a camera's depth buffer (shaders/depth_bounds_comp.glsl) read back at once, so
// the cascades of the same frame use it (no frame of latency).
#include "renderer/csm/depth_bounds.h"
#include "renderer/gpu/gl.h"
#include "renderer/render/shader_library.h"
#include "renderer/gpu/uniform_buffer.h"
#include "shaders/interface.h"

#include <glm/mat4x4.hpp>

#include <optional>
#include <span>
#include <vector>

namespace st {

class DepthBoundsPass {
public:
    DepthBoundsPass();  // needs a current GL 4.5 core context

    // Nearest and farthest view depth of the non-background texels of `depth` (a D32F texture
    // of width x height drawn through csProj, GL depth [0, 1]); nullopt when there is none.
    std::optional<csm::DepthRange> depthRange(GLuint depth, int width, int height, const glm::mat4& csProj);

    // In one pass, the depth range as depthRange() and, per cascade i (view depths
    // splits[i]..splits[i+1]), the bounds in ls = vsToLs * vs of the texels it holds (nullopt for
    // a cascade that holds none). For splits that do not follow the seen range.
    csm::SampleBounds cascadeBounds(GLuint depth, int width, int height, const glm::mat4& csProj,
                                    const glm::mat4& vsToLs, std::span<const float> splits);

private:
    struct Result;
    Result run(GLuint depth, const gpu_if::ReduceBlock& block);
    SharedProgram program_;
    gpu::Buffer result_;
    gpu::UniformBuffer<gpu_if::ReduceBlock> block_;
};

}  // namespace st
