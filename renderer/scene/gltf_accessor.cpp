// Accessors: validated against their buffer view and buffer (never trusting tinygltf), then read.
#include "renderer/scene/gltf_detail.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace st::gltf {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

namespace {

std::size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

int typeComponents(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
    }
}

std::string typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    default: return "type " + std::to_string(type);
    }
}

template <class T>
T load(const std::uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

// glTF 2.0 §3.11: normalized integers map to [0, 1] or [-1, 1].
float readComponent(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float v = load<std::int8_t>(p);
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const float v = load<std::uint16_t>(p);
        return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const float v = load<std::int16_t>(p);
        return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    default: return float(load<std::uint32_t>(p));
    }
}

template <int N>
std::vector<glm::vec<N, float>> readVectors(const AccessorView& view) {
    std::vector<glm::vec<N, float>> out(view.count);
    const std::size_t size = componentSize(view.componentType);
    const int n = std::min(N, view.components);
    for (std::size_t i = 0; i < view.count; ++i) {
        const std::uint8_t* element = view.data + i * view.stride;
        for (int c = 0; c < n; ++c) out[i][c] = readComponent(element + c * size, view.componentType, view.normalized);
    }
    return out;
}

// Checks the buffer view and the accessor's byte range; returns the first element's address.
const std::uint8_t* checkedData(LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Accessor& a,
                                std::size_t elementSize, std::size_t& stride, const std::string& label) {
    if (a.bufferView >= static_cast<int>(model.bufferViews.size())) {
        ctx.fail(label + " refers to buffer view " + std::to_string(a.bufferView) + ", but the file has " +
                 std::to_string(model.bufferViews.size()));
    }
    const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::string bvLabel = "buffer view " + std::to_string(a.bufferView);
    if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model.buffers.size())) {
        ctx.fail(bvLabel + " refers to buffer " + std::to_string(bv.buffer) + ", which does not exist");
    }
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset) {
        ctx.fail(bvLabel + " overruns buffer " + std::to_string(bv.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    }
    stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
    if (stride < elementSize) {
        ctx.fail(label + " has " + std::to_string(elementSize) + "-byte elements but " + bvLabel +
                 " has byteStride " + std::to_string(stride));
    }
    const std::uint64_t span = std::uint64_t(stride) * (a.count - 1) + elementSize;  // count <= limits
    if (a.byteOffset > bv.byteLength || span > bv.byteLength - a.byteOffset) {
        ctx.fail(label + " needs bytes [" + std::to_string(a.byteOffset) + ", " + std::to_string(a.byteOffset + span) +
                 ") of " + bvLabel + ", which has only " + std::to_string(bv.byteLength) + " bytes");
    }
    return data.data() + bv.byteOffset + a.byteOffset;
}

}  // namespace

std::optional<AccessorView> viewAccessor(LoadContext& ctx, const tinygltf::Model& model, int index,
                                         int expectedType, const std::string& role) {
    if (index < 0 || index >= static_cast<int>(model.accessors.size())) {
        ctx.fail(role + " refers to accessor " + std::to_string(index) + ", but the file has " +
                 std::to_string(model.accessors.size()) + " accessors");
    }
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    const std::string label = "accessor " + std::to_string(index) + " (" + role + ")";
    if (a.type != expectedType) ctx.fail(label + " has type " + typeName(a.type) + ", expected " + typeName(expectedType));
    const std::size_t size = componentSize(a.componentType);
    if (size == 0) ctx.fail(label + " has unsupported componentType " + std::to_string(a.componentType));
    const bool indices = expectedType == TINYGLTF_TYPE_SCALAR;
    const std::uint64_t limit = indices ? ctx.limits.maxIndices : ctx.limits.maxVertices;
    if (a.count > limit) {
        ctx.fail(label + " has " + std::to_string(a.count) + " elements, above the limit of " + std::to_string(limit) +
                 (indices ? " (GltfLimits::maxIndices)" : " (GltfLimits::maxVertices)"));
    }
    if (a.sparse.isSparse) {
        ctx.warn(label + " is sparse, which is not supported: the primitive is skipped");
        return std::nullopt;
    }
    if (a.bufferView < 0) {
        ctx.warn(label + " has no buffer view (all zeros): the primitive is skipped");
        return std::nullopt;
    }
    AccessorView view;
    view.count = a.count;
    view.components = typeComponents(a.type);
    view.componentType = a.componentType;
    view.normalized = a.normalized;
    if (a.count == 0) ctx.fail(label + " has count 0");
    view.data = checkedData(ctx, model, a, size * static_cast<std::size_t>(view.components), view.stride, label);
    return view;
}

std::vector<glm::vec3> readVec3(const AccessorView& view) { return readVectors<3>(view); }
std::vector<glm::vec2> readVec2(const AccessorView& view) { return readVectors<2>(view); }

std::vector<std::uint32_t> readIndices(LoadContext& ctx, const AccessorView& view, const std::string& role) {
    const int type = view.componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        ctx.fail(role + " indices must be unsigned byte, short or int, not componentType " + std::to_string(type));
    }
    std::vector<std::uint32_t> out(view.count);
    for (std::size_t i = 0; i < view.count; ++i) {
        const std::uint8_t* p = view.data + i * view.stride;
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) out[i] = *p;
        else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) out[i] = load<std::uint16_t>(p);
        else out[i] = load<std::uint32_t>(p);
    }
    return out;
}

}  // namespace st::gltf
