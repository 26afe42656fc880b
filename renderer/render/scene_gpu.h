#pragma once
// The scene's vertices, indices and textures on the GPU, and how to issue one DrawItem.
#include "renderer/gpu/gl.h"
#include "renderer/scene/scene.h"

#include <vector>

namespace st {

class SceneGpu {
public:
    explicit SceneGpu(const Scene& scene);
    const Scene& scene() const { return *scene_; }
    void bindGeometry() const;
    // Sets the material uniforms of `program` (uBaseColor, uHasTexture, uAlphaMask, ...) and
    // binds the base-colour texture; then draws the item's triangles. cullBackFaces: enable
    // back-face culling unless the material is double-sided (main pass); false leaves it alone.
    void draw(GLuint program, const DrawItem& item, bool cullBackFaces) const;

private:
    const Scene* scene_;
    gpu::Buffer vertices_;
    gpu::Buffer indices_;
    gpu::VertexArray vao_;
    std::vector<gpu::Texture> textures_;
    gpu::Texture white_;
};

}  // namespace st
