#include "renderer/render/shader_blocks.h"

#include "renderer/csm/conventions.h"
#include "renderer/csm/filter_weights.h"
#include "renderer/render/side_view.h"
#include "renderer/settings/field_table.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace st {
namespace {
void store(const FieldInfo& field, const gpu_if::MemberInfo& member, const Settings& s, void* block) {
    auto* at = static_cast<char*>(block) + member.offset;
    const FieldValue value = field.get(s);
    if (member.type == gpu_if::MemberType::Float && field.kind == FieldKind::Float) {
        std::memcpy(at, &std::get<float>(value), sizeof(float));
        return;
    }
    if (member.type == gpu_if::MemberType::Int) {
        int code = 0;
        if (field.kind == FieldKind::Int || field.kind == FieldKind::Enum) code = std::get<int>(value);
        else if (field.kind == FieldKind::Bool) code = std::get<bool>(value) ? 1 : 0;
        else throw std::logic_error(std::string(field.path) + " cannot feed int member " + std::string(member.name));
        std::memcpy(at, &code, sizeof(int));
        return;
    }
    throw std::logic_error(std::string(field.path) + " (" + std::string(fieldKindName(field.kind)) +
                           ") does not match the type of shader member " + std::string(member.name));
}
}  // namespace

// exp(c) of the warp must stay finite and its square representable: 42 for 32-bit floats
// (e^84 < 3.4e38) and 5.54 for 16-bit ones (e^11.08 < 65504), Lauritzen & McCool 2008.
float evsmExponent(float requested, bool sixteenBit) { return std::min(requested, sixteenBit ? 5.54f : 42.0f); }

void copyShaderFields(const Settings& s, std::span<const gpu_if::MemberInfo> members, void* block) {
    for (const FieldInfo& field : fieldTable()) {
        if (field.shader.empty()) continue;
        for (const gpu_if::MemberInfo& member : members)
            if (member.name == field.shader) store(field, member, s, block);
    }
}

gpu_if::FrameBlock frameBlock(const Settings& s, const csm::CascadePlan& plan) {
    gpu_if::FrameBlock b;
    copyShaderFields(s, b);
    b.view = plan.vsView;
    b.wsToSun = glm::vec4(-plan.wsLightDir, 0.0f);
    return b;
}

gpu_if::CascadeBlock cascadeBlock(const Settings& s, const csm::CascadePlan& plan) {
    gpu_if::CascadeBlock b;
    copyShaderFields(s, b);
    const auto w = csm::pcfWeights(s.filter.weights, s.filter.size);
    for (std::size_t k = 0; k < w.size(); ++k) b.pcfWeights[k / 4][static_cast<int>(k % 4)] = w[k];
    const auto blur = csm::blurWeights(s.filter.blurRadius);
    for (std::size_t k = 0; k < blur.size(); ++k) b.blurWeights[k / 4][static_cast<int>(k % 4)] = blur[k];
    b.evsmPosExp = evsmExponent(s.filter.evsmPositive, s.filter.moments16);
    b.evsmNegExp = evsmExponent(s.filter.evsmNegative, s.filter.moments16);
    b.sunTan = std::tan(glm::radians(s.light.angularDiameter));
    b.normalOffset = receiverNormalOffset(s.bias);  // 0 when the casters move instead (caster_pass.cpp)
    for (int i = 0; i < s.cascades.count; ++i) {
        const csm::CascadeFit& f = plan.cascades[static_cast<std::size_t>(i)];
        gpu_if::CascadeData& c = b.cascade[i];
        const csm::MapTile& tile = plan.storage.tiles[static_cast<std::size_t>(i)];
        const csm::MapTexture& texture = plan.storage.textures[static_cast<std::size_t>(tile.texture)];
        // Seed 003's tile matrix folded in: ws straight to the uv of the cascade's own tile.
        c.shadowMatrix = csm::tileMatrix(tile, texture) * csm::clipToTexture() * f.viewProj;
        c.tileBounds = csm::tileBounds(tile, texture);
        c.uvPerTexel = glm::vec4(1.0f / float(texture.width), 1.0f / float(texture.height), 0.0f, 0.0f);
        c.padding = float(plan.storage.padding);
        c.layer = tile.layer;
        c.tint = glm::vec4(cascadeTint(i), 1.0f);
        c.vsNear = plan.splits[static_cast<std::size_t>(i)];
        c.vsFar = plan.splits[static_cast<std::size_t>(i) + 1];
        c.texelWorld = f.texelWorldSize;
        c.depthRange = f.lsBox.extent().z;
        const BiasSettings& bias = s.bias;
        c.biasScale = glm::vec4(cascadeFactor(bias.constantScale, i), cascadeFactor(bias.slopeScale, i),
                                cascadeFactor(bias.normalOffsetScale, i), 0.0f);
    }
    return b;
}

gpu_if::MaterialBlock materialBlock(const Material& m, bool textured) {
    gpu_if::MaterialBlock b;
    b.baseColor = m.baseColor;
    b.hasTexture = textured ? 1 : 0;
    b.alphaMask = m.alphaMask ? 1 : 0;
    b.alphaCutoff = m.alphaCutoff;
    return b;
}

}  // namespace st
