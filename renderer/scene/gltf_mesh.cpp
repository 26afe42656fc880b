// One primitive instance to world-space vertices, indices and a DrawItem.
#include "renderer/scene/gltf_detail.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace st::gltf {

namespace {

struct PrimitiveData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // empty: flat normals
    std::vector<glm::vec2> uvs;          // empty: zeros
    std::vector<std::uint32_t> indices;  // a multiple of 3, all < positions.size()
};

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

int attribute(const tinygltf::Primitive& p, const char* name) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

std::vector<std::uint32_t> readTriangleIndices(LoadContext& ctx, const tinygltf::Model& model,
                                               const tinygltf::Primitive& p, std::size_t vertexCount,
                                               const std::string& label, bool& skipped) {
    std::vector<std::uint32_t> indices;
    if (p.indices < 0) {
        indices.resize(vertexCount);
        std::iota(indices.begin(), indices.end(), 0u);
    } else if (auto view = viewAccessor(ctx, model, p.indices, TINYGLTF_TYPE_SCALAR, "indices of " + label)) {
        indices = readIndices(ctx, *view, label);
    } else {
        skipped = true;
        return indices;
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertexCount) {
            ctx.fail(label + " index " + std::to_string(indices[i]) + " (at position " + std::to_string(i) +
                     ") is out of range: the primitive has " + std::to_string(vertexCount) + " vertices");
        }
    }
    if (indices.size() % 3 != 0) {
        ctx.warn(label + " has " + std::to_string(indices.size()) + " indices, not a multiple of 3: the rest is dropped");
        indices.resize(indices.size() - indices.size() % 3);
    }
    return indices;
}

// Optional attribute; its count must cover every vertex.
template <class Read>
auto readAttribute(LoadContext& ctx, const tinygltf::Model& model, int accessor, int type, std::size_t vertexCount,
                   const std::string& role, bool& skipped, Read read) -> decltype(read(AccessorView{})) {
    if (accessor < 0) return {};
    auto view = viewAccessor(ctx, model, accessor, type, role);
    if (!view) {
        skipped = true;
        return {};
    }
    if (view->count < vertexCount) {
        ctx.fail(role + " has " + std::to_string(view->count) + " elements but POSITION has " + std::to_string(vertexCount));
    }
    return read(*view);
}

// nullopt: skipped with a warning.
std::optional<PrimitiveData> readPrimitive(LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& p,
                                           const std::string& label) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES) {
        ctx.warn(label + " has mode " + std::to_string(p.mode) + ", not TRIANGLES (4): skipped");
        return std::nullopt;
    }
    const int position = attribute(p, "POSITION");
    if (position < 0) {
        ctx.warn(label + " has no POSITION: skipped");
        return std::nullopt;
    }
    bool skipped = false;
    PrimitiveData data;
    data.positions = readAttribute(ctx, model, position, TINYGLTF_TYPE_VEC3, 0, "POSITION of " + label, skipped, readVec3);
    if (skipped) return std::nullopt;
    for (std::size_t i = 0; i < data.positions.size(); ++i) {
        if (!finite(data.positions[i])) {
            ctx.fail("POSITION of " + label + " has a non-finite value (NaN or inf) at vertex " + std::to_string(i));
        }
    }
    const std::size_t n = data.positions.size();
    data.indices = readTriangleIndices(ctx, model, p, n, label, skipped);
    data.normals = readAttribute(ctx, model, attribute(p, "NORMAL"), TINYGLTF_TYPE_VEC3, n, "NORMAL of " + label, skipped, readVec3);
    data.uvs = readAttribute(ctx, model, attribute(p, "TEXCOORD_0"), TINYGLTF_TYPE_VEC2, n, "TEXCOORD_0 of " + label, skipped, readVec2);
    if (skipped) return std::nullopt;
    return data;
}

// World-space normals, or empty when some are unusable (then flat normals are generated).
std::vector<glm::vec3> worldNormals(LoadContext& ctx, const PrimitiveData& data, const MeshInstance& instance,
                                    const std::string& label) {
    if (data.normals.empty() || instance.singular) return {};
    std::vector<glm::vec3> out(data.positions.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const glm::vec3 n = instance.wsNormalFromLocal * data.normals[i];
        const float length = glm::length(n);
        if (!(length > 1e-20f) || !std::isfinite(length)) {
            ctx.warn(label + " has NORMAL vectors that are zero or not finite: flat normals generated");
            return {};
        }
        out[i] = n / length;
    }
    return out;
}

void checkBudget(LoadContext& ctx, const Scene& scene, std::uint64_t vertices, std::uint64_t indices,
                 const std::string& label) {
    if (scene.vertices.size() + vertices > ctx.limits.maxVertices) {
        ctx.fail(label + " takes the scene above " + std::to_string(ctx.limits.maxVertices) +
                 " vertices (GltfLimits::maxVertices)");
    }
    if (scene.indices.size() + indices > ctx.limits.maxIndices) {
        ctx.fail(label + " takes the scene above " + std::to_string(ctx.limits.maxIndices) +
                 " indices (GltfLimits::maxIndices)");
    }
    ctx.chargeDecoded(vertices * sizeof(Vertex) + indices * sizeof(std::uint32_t), label);
}

Vertex worldVertex(LoadContext& ctx, const PrimitiveData& data, std::uint32_t i, const MeshInstance& instance,
                   const std::string& label) {
    Vertex v;
    v.position = glm::vec3(instance.wsFromLocal * glm::vec4(data.positions[i], 1.0f));
    if (!finite(v.position)) ctx.fail(instance.nodeLabel + " moves " + label + " to a non-finite position");
    if (!data.uvs.empty()) v.uv = data.uvs[i];
    if (!std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) v.uv = glm::vec2(0.0f);
    return v;
}

// Three vertices per triangle, normal = face normal of the (counter-clockwise) world triangle.
void emitFlat(LoadContext& ctx, const PrimitiveData& data, const MeshInstance& instance, Scene& scene,
              const std::string& label) {
    const auto base = static_cast<std::uint32_t>(scene.vertices.size());
    for (std::size_t t = 0; t < data.indices.size(); t += 3) {
        std::uint32_t corner[3] = {data.indices[t], data.indices[t + 1], data.indices[t + 2]};
        if (instance.flipWinding) std::swap(corner[1], corner[2]);
        Vertex v[3];
        for (int k = 0; k < 3; ++k) v[k] = worldVertex(ctx, data, corner[k], instance, label);
        glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        const float length = glm::length(n);
        n = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
        for (Vertex& out : v) {
            out.normal = n;
            scene.vertices.push_back(out);
        }
    }
    for (std::uint32_t i = 0; i < data.indices.size(); ++i) scene.indices.push_back(base + i);
}

void emitShared(LoadContext& ctx, const PrimitiveData& data, const std::vector<glm::vec3>& normals,
                const MeshInstance& instance, Scene& scene, const std::string& label) {
    const auto base = static_cast<std::uint32_t>(scene.vertices.size());
    for (std::uint32_t i = 0; i < data.positions.size(); ++i) {
        Vertex v = worldVertex(ctx, data, i, instance, label);
        v.normal = normals[i];
        scene.vertices.push_back(v);
    }
    for (std::size_t t = 0; t < data.indices.size(); t += 3) {
        const int second = instance.flipWinding ? 2 : 1;
        scene.indices.push_back(base + data.indices[t]);
        scene.indices.push_back(base + data.indices[t + static_cast<std::size_t>(second)]);
        scene.indices.push_back(base + data.indices[t + static_cast<std::size_t>(3 - second)]);
    }
}

// Primitives without a material use one default Material appended after the file's materials.
int materialIndex(LoadContext& ctx, const tinygltf::Model& model, int material, const std::string& label) {
    const int count = static_cast<int>(model.materials.size());
    if (material >= count) {
        ctx.fail(label + " refers to material " + std::to_string(material) + ", but the file has " +
                 std::to_string(count) + " materials");
    }
    if (material >= 0) return material;
    ctx.usesDefaultMaterial = true;
    return count;
}

csm::Aabb boundsOf(const Scene& scene, std::size_t firstVertex) {
    csm::Aabb box{scene.vertices[firstVertex].position, scene.vertices[firstVertex].position};
    for (std::size_t i = firstVertex; i < scene.vertices.size(); ++i) {
        box.min = glm::min(box.min, scene.vertices[i].position);
        box.max = glm::max(box.max, scene.vertices[i].position);
    }
    return box;
}

}  // namespace

void appendPrimitive(LoadContext& ctx, const tinygltf::Model& model, int mesh, int primitive,
                     const MeshInstance& instance, Scene& scene, GeometryStats& stats) {
    const std::string label = "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
    const tinygltf::Primitive& p = model.meshes[static_cast<std::size_t>(mesh)].primitives[static_cast<std::size_t>(primitive)];
    const std::optional<PrimitiveData> data = readPrimitive(ctx, model, p, label);
    if (!data || data->indices.empty()) {
        if (data) ctx.warn(label + " has no triangles: skipped");
        ++stats.primitivesSkipped;
        return;
    }
    DrawItem draw;
    draw.material = materialIndex(ctx, model, p.material, label);
    const std::vector<glm::vec3> normals = worldNormals(ctx, *data, instance, label);
    const std::size_t vertexCount = normals.empty() ? data->indices.size() : data->positions.size();
    checkBudget(ctx, scene, vertexCount, data->indices.size(), label + " of " + instance.nodeLabel);
    const std::size_t firstVertex = scene.vertices.size();
    draw.firstIndex = static_cast<std::uint32_t>(scene.indices.size());
    draw.indexCount = static_cast<std::uint32_t>(data->indices.size());
    if (normals.empty()) emitFlat(ctx, *data, instance, scene, label);
    else emitShared(ctx, *data, normals, instance, scene, label);
    draw.wsBounds = boundsOf(scene, firstVertex);
    scene.draws.push_back(draw);
}

}  // namespace st::gltf
