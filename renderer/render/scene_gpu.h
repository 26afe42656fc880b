#pragma once
// The scene's vertices, indices, textures and materials on the GPU, and how to issue one DrawItem.
#include "renderer/gpu/gl.h"
#include "renderer/scene/scene.h"

#include <vector>

namespace st {

enum class FaceCulling {
    Keep,         // leave the pass's state alone (the shadow pass: casters cast from both sides)
    PerMaterial,  // cull back faces unless the material is double-sided (main and measure passes)
};

class SceneGpu {
public:
    explicit SceneGpu(const Scene& scene);
    const Scene& scene() const { return *scene_; }
    void bindGeometry() const;
    // Binds the item's MaterialBlock (ST_BLOCK_MATERIAL) and base-colour texture, then draws
    // the item's triangles.
    void draw(const DrawItem& item, FaceCulling culling) const;

private:
    int materialIndex(const DrawItem& item) const;  // a valid index; the default material last

    const Scene* scene_;
    gpu::Buffer vertices_;
    gpu::Buffer indices_;
    gpu::VertexArray vao_;
    std::vector<gpu::Texture> textures_;
    gpu::Texture white_;
    // Every material's block, one per stride (GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT), uploaded once.
    gpu::Buffer materials_;
    GLsizeiptr materialStride_ = 0;
    std::vector<bool> materialDoubleSided_;
    std::vector<GLuint> materialTexture_;
};

}  // namespace st
