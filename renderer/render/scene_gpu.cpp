#include "renderer/render/scene_gpu.h"

#include "renderer/render/shader_blocks.h"
#include "shaders/interface.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

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

gpu::VertexArray sceneVertexArray(const gpu::Buffer& vertices, const gpu::Buffer& indices) {
    gpu::VertexArray vao = gpu::createVertexArray();
    GLuint v = vao.id();
    glVertexArrayVertexBuffer(v, 0, vertices.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(v, indices.id());
    struct Attrib { GLuint location; GLint size; GLuint offset; };
    const Attrib attribs[3] = {{ST_ATTRIB_POSITION, 3, offsetof(Vertex, position)},
                               {ST_ATTRIB_NORMAL, 3, offsetof(Vertex, normal)},
                               {ST_ATTRIB_UV, 2, offsetof(Vertex, uv)}};
    for (const Attrib& a : attribs) {
        glEnableVertexArrayAttrib(v, a.location);
        glVertexArrayAttribFormat(v, a.location, a.size, GL_FLOAT, GL_FALSE, a.offset);
        glVertexArrayAttribBinding(v, a.location, 0);
    }
    return vao;
}

GLsizeiptr uniformStride(std::size_t bytes) {
    GLint align = 256;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
    const auto a = static_cast<GLsizeiptr>(std::max(align, 1));
    return (static_cast<GLsizeiptr>(bytes) + a - 1) / a * a;
}
}  // namespace

SceneGpu::SceneGpu(const Scene& scene) : scene_(&scene) {
    static std::atomic<std::uint64_t> made{0};
    serial_ = ++made;
    vertices_ = gpu::createBuffer(scene.vertices.data(),
                                  static_cast<GLsizeiptr>(scene.vertices.size() * sizeof(Vertex)));
    indices_ = gpu::createBuffer(scene.indices.data(),
                                 static_cast<GLsizeiptr>(scene.indices.size() * sizeof(std::uint32_t)));
    clustered_ = buildClusters(scene);
    clusteredIndices_ = gpu::createBuffer(
        clustered_.indices.data(), static_cast<GLsizeiptr>(clustered_.indices.size() * sizeof(std::uint32_t)));
    vao_ = sceneVertexArray(vertices_, indices_);
    clusteredVao_ = sceneVertexArray(vertices_, clusteredIndices_);
    for (const Image& img : scene.images) textures_.push_back(uploadImage(img));
    white_ = uploadImage(Image{1, 1, {255, 255, 255, 255}});

    std::vector<Material> materials = scene.materials;
    materials.push_back(Material{});  // for draws whose index is out of range
    materialStride_ = uniformStride(sizeof(gpu_if::MaterialBlock));
    std::vector<std::byte> blocks(static_cast<std::size_t>(materialStride_) * materials.size());
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& m = materials[i];
        const bool textured = m.baseColorTexture >= 0 && m.baseColorTexture < static_cast<int>(textures_.size());
        const gpu_if::MaterialBlock b = materialBlock(m, textured);
        std::memcpy(blocks.data() + i * static_cast<std::size_t>(materialStride_), &b, sizeof b);
        materialDoubleSided_.push_back(m.doubleSided);
        materialMasked_.push_back(m.alphaMask);
        materialTexture_.push_back(textured ? textures_[static_cast<std::size_t>(m.baseColorTexture)].id() : white_.id());
    }
    materials_ = gpu::createBuffer(blocks.data(), static_cast<GLsizeiptr>(blocks.size()));
}

void SceneGpu::bindGeometry() const { glBindVertexArray(vao_.id()); }

int SceneGpu::materialIndex(int material) const {
    const int count = static_cast<int>(scene_->materials.size());
    return material >= 0 && material < count ? material : count;
}

void SceneGpu::bindMaterial(int material, FaceCulling culling) const {
    const auto m = static_cast<std::size_t>(materialIndex(material));
    glBindBufferRange(GL_UNIFORM_BUFFER, ST_BLOCK_MATERIAL, materials_.id(),
                      static_cast<GLintptr>(m) * materialStride_, sizeof(gpu_if::MaterialBlock));
    glBindTextureUnit(ST_BINDING_BASE_COLOR, materialTexture_[m]);
    if (culling == FaceCulling::PerMaterial) {
        if (materialDoubleSided_[m]) glDisable(GL_CULL_FACE);
        else glEnable(GL_CULL_FACE);
    }
}

void SceneGpu::draw(const DrawItem& item, FaceCulling culling) const {
    bindMaterial(item.material, culling);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(item.indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(item.firstIndex) * 4));
}

void SceneGpu::bindClusteredGeometry() const { glBindVertexArray(clusteredVao_.id()); }

void SceneGpu::drawBatches(const DrawBatches& batches, FaceCulling culling) const {
    std::vector<const void*> offsets;
    for (const DrawBatch& b : batches.batches()) {
        bindMaterial(b.material, culling);
        multiDraw(b, offsets);
    }
}

void SceneGpu::multiDraw(const DrawBatch& b, std::vector<const void*>& offsets) const {
    offsets.clear();
    for (std::uintptr_t o : b.byteOffsets) offsets.push_back(reinterpret_cast<const void*>(o));
    glMultiDrawElements(GL_TRIANGLES, b.counts.data(), GL_UNSIGNED_INT, offsets.data(), static_cast<GLsizei>(b.counts.size()));
}

void SceneGpu::drawDepthBatches(const DrawBatches& batches, FaceCulling culling, const DepthPrograms& programs) const {
    GLuint bound = 0;
    std::vector<const void*> offsets;
    for (const DrawBatch& b : batches.batches()) {
        const bool masked = materialMasked_[static_cast<std::size_t>(materialIndex(b.material))];
        if (const GLuint program = masked ? programs.masked : programs.opaque; program != bound) glUseProgram(bound = program);
        bindMaterial(b.material, culling);
        multiDraw(b, offsets);
    }
}

}  // namespace st
