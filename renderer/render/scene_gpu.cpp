#include "renderer/render/scene_gpu.h"

#include "shaders/limits.h"

#include <cstddef>

namespace st {
namespace {
gpu::Texture uploadImage(const Image& img) {
    gpu::Texture t = gpu::createTexture(GL_TEXTURE_2D);
    int levels = 1;
    for (int s = std::max(img.width, img.height); s > 1; s /= 2) ++levels;
    glTextureStorage2D(t.id(), levels, GL_SRGB8_ALPHA8, img.width, img.height);
    glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        img.rgba.data());
    glGenerateTextureMipmap(t.id());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return t;
}
}  // namespace

SceneGpu::SceneGpu(const Scene& scene) : scene_(&scene) {
    vertices_ = gpu::createBuffer(scene.vertices.data(),
                                  static_cast<GLsizeiptr>(scene.vertices.size() * sizeof(Vertex)));
    indices_ = gpu::createBuffer(scene.indices.data(),
                                 static_cast<GLsizeiptr>(scene.indices.size() * sizeof(std::uint32_t)));
    vao_ = gpu::createVertexArray();
    GLuint v = vao_.id();
    glVertexArrayVertexBuffer(v, 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(v, indices_.id());
    const GLuint offsets[3] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(v, a);
        glVertexArrayAttribFormat(v, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(v, a, 0);
    }
    for (const Image& img : scene.images) textures_.push_back(uploadImage(img));
    white_ = uploadImage(Image{1, 1, {255, 255, 255, 255}});
}

void SceneGpu::bindGeometry() const { glBindVertexArray(vao_.id()); }

void SceneGpu::draw(GLuint program, const DrawItem& item, bool cullBackFaces) const {
    static const Material kDefault;
    const Material& m = item.material >= 0 && item.material < static_cast<int>(scene_->materials.size())
                            ? scene_->materials[item.material]
                            : kDefault;
    bool textured = m.baseColorTexture >= 0 && m.baseColorTexture < static_cast<int>(textures_.size());
    glBindTextureUnit(ST_BINDING_BASE_COLOR, textured ? textures_[m.baseColorTexture].id() : white_.id());
    glProgramUniform4fv(program, glGetUniformLocation(program, "uBaseColor"), 1, &m.baseColor.x);
    glProgramUniform1f(program, glGetUniformLocation(program, "uBaseAlpha"), m.baseColor.a);
    glProgramUniform1i(program, glGetUniformLocation(program, "uHasTexture"), textured);
    glProgramUniform1i(program, glGetUniformLocation(program, "uAlphaMask"), m.alphaMask);
    glProgramUniform1f(program, glGetUniformLocation(program, "uAlphaCutoff"), m.alphaCutoff);
    if (cullBackFaces) {
        if (m.doubleSided) glDisable(GL_CULL_FACE);
        else glEnable(GL_CULL_FACE);
    }
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(item.indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(item.firstIndex) * 4));
}

}  // namespace st
