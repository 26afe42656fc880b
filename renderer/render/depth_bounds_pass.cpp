#include "renderer/render/depth_bounds_pass.h"

#include "renderer/render/shader_library.h"

#include <glm/matrix.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace st {

// shaders/depth_bounds_comp.glsl's ReduceResult (std430: uint arrays are tightly packed).
struct DepthBoundsPass::Result {
    std::uint32_t depthKeys[4];
    std::uint32_t lsMinKeys[3 * ST_MAX_CASCADES];
    std::uint32_t lsMaxKeys[3 * ST_MAX_CASCADES];
    std::uint32_t lsSamples[ST_MAX_CASCADES];
};

namespace {

constexpr int kGroupWidth = 8 * 16;  // local_size_x of the shader times its TILE
constexpr int kGroupHeight = 16;     // local_size_y (1) times TILE

// Inverse of the shader's orderedKey().
float fromKey(std::uint32_t key) {
    const std::uint32_t bits = (key & 0x80000000u) ? (key & 0x7fffffffu) : ~key;
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

gpu::Program linkCompute(const std::string& file) {
    const ExpandedShader src = expandShader(file);
    try {
        return gpu::linkComputeProgram(src.text, file);
    } catch (const gpu::ShaderCompileError& e) {
        throw std::runtime_error("shader " + file + " failed to compile:\n" + nameLogFiles(e.log, src.files));
    }
}

}  // namespace

DepthBoundsPass::DepthBoundsPass()
    : program_(sharedProgram("depth_bounds_comp.glsl", [] { return linkCompute("depth_bounds_comp.glsl"); })) {
    result_ = gpu::createBuffer(nullptr, sizeof(Result), GL_DYNAMIC_STORAGE_BIT);
}

DepthBoundsPass::Result DepthBoundsPass::run(GLuint depth, const gpu_if::ReduceBlock& block) {
    gpu::DebugGroup group("depth bounds");
    Result r{};
    r.depthKeys[0] = 0xffffffffu;
    for (std::uint32_t& k : r.lsMinKeys) k = 0xffffffffu;
    glNamedBufferSubData(result_.id(), 0, sizeof r, &r);
    block_.upload(block);
    block_.bind(ST_BLOCK_REDUCE);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ST_STORAGE_REDUCE, result_.id());
    glBindTextureUnit(ST_BINDING_REDUCE_DEPTH, depth);
    glUseProgram(program_->id());
    glDispatchCompute(GLuint((block.reduceWidth + kGroupWidth - 1) / kGroupWidth),
                      GLuint((block.reduceHeight + kGroupHeight - 1) / kGroupHeight), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(result_.id(), 0, sizeof r, &r);
    glBindTextureUnit(ST_BINDING_REDUCE_DEPTH, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ST_STORAGE_REDUCE, 0);
    return r;
}

namespace {

// The reduced GL depths [min, max] as view depths: a perspective's view depth follows its GL depth
// monotonically and does not depend on the pixel, so the two ends are the range.
std::optional<csm::DepthRange> viewDepthRange(const std::uint32_t keys[4], const glm::mat4& invProj) {
    if (keys[2] == 0) return std::nullopt;
    auto viewDepth = [&](float d) {
        const glm::vec4 vs = invProj * glm::vec4(0.0f, 0.0f, d * 2.0f - 1.0f, 1.0f);
        return -vs.z / vs.w;
    };
    return csm::DepthRange{viewDepth(fromKey(keys[0])), viewDepth(fromKey(keys[1]))};
}

// Mode 0 (the depth range) of a width x height depth buffer drawn through csProj.
gpu_if::ReduceBlock reduceBlock(const glm::mat4& csProj, int width, int height) {
    gpu_if::ReduceBlock b;
    b.reduceInvProj = glm::inverse(csProj);
    b.reduceMode = 0;
    b.reduceWidth = width;
    b.reduceHeight = height;
    return b;
}

}  // namespace

std::optional<csm::DepthRange> DepthBoundsPass::depthRange(GLuint depth, int width, int height,
                                                           const glm::mat4& csProj) {
    const gpu_if::ReduceBlock b = reduceBlock(csProj, width, height);
    const Result r = run(depth, b);
    return viewDepthRange(r.depthKeys, b.reduceInvProj);
}

csm::SampleBounds DepthBoundsPass::cascadeBounds(GLuint depth, int width, int height, const glm::mat4& csProj,
                                                 const glm::mat4& vsToLs, std::span<const float> splits) {
    const int count = static_cast<int>(splits.size()) - 1;
    if (count < 1 || count > ST_MAX_CASCADES)
        throw std::invalid_argument("depth bounds: " + std::to_string(splits.size()) + " split depths");
    gpu_if::ReduceBlock b = reduceBlock(csProj, width, height);
    b.reduceVsToLs = vsToLs;
    for (std::size_t i = 0; i < splits.size(); ++i) b.reduceSplits[i / 4][int(i % 4)] = splits[i];
    b.reduceMode = 1;
    b.reduceCascades = count;
    const Result r = run(depth, b);
    csm::SampleBounds out;
    out.depth = viewDepthRange(r.depthKeys, b.reduceInvProj);
    out.lsCascade.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        if (r.lsSamples[i] == 0) continue;
        csm::Aabb box;
        for (int k = 0; k < 3; ++k) {
            box.min[k] = fromKey(r.lsMinKeys[3 * i + k]);
            box.max[k] = fromKey(r.lsMaxKeys[3 * i + k]);
        }
        out.lsCascade[static_cast<std::size_t>(i)] = box;
    }
    return out;
}

}  // namespace st
