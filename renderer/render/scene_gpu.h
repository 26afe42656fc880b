#pragma once
// The scene's vertices, indices, textures and materials on the GPU, and how to issue one DrawItem.
#include "renderer/gpu/gl.h"
#include "renderer/render/draw_batches.h"
#include "renderer/scene/clusters.h"
#include "renderer/scene/scene.h"

#include <cstdint>
#include <vector>

namespace st {

enum class FaceCulling {
    Keep,         // leave the pass's state alone (the shadow pass: casters cast from both sides)
    PerMaterial,  // cull back faces unless the material is double-sided (main and measure passes)
};

// The programs of a depth-only pass: llvmpipe rasterises depth about three times as fast with an
// empty fragment shader as with one that may discard (truck-town's tuned preset, three 1024²
// maps: 18 against 47 ms GPU shadow), so only alpha-masked materials take the alpha-tested one.
struct DepthPrograms {
    GLuint opaque = 0;
    GLuint masked = 0;
};

class SceneGpu {
public:
    explicit SceneGpu(const Scene& scene);
    const Scene& scene() const { return *scene_; }
    // Unique to this object among all made in the process: what a cache keyed on "this scene's
    // geometry on the GPU" keys on (an address can be reused by the next one).
    std::uint64_t serial() const { return serial_; }
    void bindGeometry() const;
    // Binds the item's MaterialBlock (ST_BLOCK_MATERIAL) and base-colour texture, then draws
    // the item's triangles.
    void draw(const DrawItem& item, FaceCulling culling) const;

    // The scene's clusters (built at construction) and their own index buffer: bind it, then
    // issue each batch's ranges with one glMultiDrawElements per material.
    const ClusteredScene& clustered() const { return clustered_; }
    void bindClusteredGeometry() const;
    void drawBatches(const DrawBatches& batches, FaceCulling culling) const;
    // A depth-only pass's batches, each with the program its material needs (left in use).
    void drawDepthBatches(const DrawBatches& batches, FaceCulling culling, const DepthPrograms& programs) const;

private:
    int materialIndex(int material) const;  // a valid index; the default material last
    void bindMaterial(int material, FaceCulling culling) const;
    // Its ranges, one glMultiDrawElements (`offsets`: the caller's scratch, reused per batch).
    void multiDraw(const DrawBatch& b, std::vector<const void*>& offsets) const;

    const Scene* scene_;
    std::uint64_t serial_;
    gpu::Buffer vertices_;
    gpu::Buffer indices_;
    gpu::VertexArray vao_;
    ClusteredScene clustered_;
    gpu::Buffer clusteredIndices_;
    gpu::VertexArray clusteredVao_;  // vertices_ with clusteredIndices_
    std::vector<gpu::Texture> textures_;
    gpu::Texture white_;
    // Every material's block, one per stride (GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT), uploaded once.
    gpu::Buffer materials_;
    GLsizeiptr materialStride_ = 0;
    std::vector<bool> materialDoubleSided_;
    std::vector<bool> materialMasked_;
    std::vector<GLuint> materialTexture_;
};

}  // namespace st
