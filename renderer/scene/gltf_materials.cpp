// Materials: base colour factor and texture, alpha mask, double-sidedness.
#include "renderer/scene/gltf_detail.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace st::gltf {

namespace {

glm::vec4 baseColorFactor(LoadContext& ctx, const std::vector<double>& factor, const std::string& label) {
    if (factor.size() != 4) {
        ctx.warn(label + " baseColorFactor has " + std::to_string(factor.size()) + " numbers, not 4: white used");
        return glm::vec4(1.0f);
    }
    glm::vec4 color;
    for (int i = 0; i < 4; ++i) {
        const double c = factor[static_cast<std::size_t>(i)];
        color[i] = std::isfinite(c) ? static_cast<float>(std::clamp(c, 0.0, 1.0)) : 1.0f;
    }
    return color;
}

// Scene::images index of a base colour texture, or -1 (warned) when it cannot be used.
class TextureImages {
public:
    TextureImages(LoadContext& ctx, const tinygltf::Model& model, Scene& scene)
        : ctx_(ctx), model_(model), scene_(scene) {}

    int imageFor(const tinygltf::TextureInfo& info, const std::string& label) {
        if (info.index < 0) return -1;
        if (info.index >= static_cast<int>(model_.textures.size())) {
            ctx_.fail(label + " refers to texture " + std::to_string(info.index) + ", but the file has " +
                      std::to_string(model_.textures.size()) + " textures");
        }
        if (info.texCoord != 0) {
            ctx_.warn(label + " reads its base colour texture with TEXCOORD_" + std::to_string(info.texCoord) +
                      "; only TEXCOORD_0 is loaded, so the texture is ignored");
            return -1;
        }
        const int source = model_.textures[static_cast<std::size_t>(info.index)].source;
        if (source < 0) {
            ctx_.warn(label + " base colour texture has no core image source (an extension's?): ignored");
            return -1;
        }
        if (source >= static_cast<int>(model_.images.size())) {
            ctx_.fail("texture " + std::to_string(info.index) + " refers to image " + std::to_string(source) +
                      ", but the file has " + std::to_string(model_.images.size()) + " images");
        }
        return decoded(source);
    }

private:
    int decoded(int source) {
        if (auto it = sceneImage_.find(source); it != sceneImage_.end()) return it->second;
        int& slot = sceneImage_[source];
        slot = -1;
        if (auto image = decodeImage(ctx_, model_.images[static_cast<std::size_t>(source)], source)) {
            slot = static_cast<int>(scene_.images.size());
            scene_.images.push_back(std::move(*image));
        }
        return slot;
    }

    LoadContext& ctx_;
    const tinygltf::Model& model_;
    Scene& scene_;
    std::map<int, int> sceneImage_;  // glTF image -> Scene::images index (-1: failed)
};

Material convertMaterial(LoadContext& ctx, const tinygltf::Material& m, const std::string& label,
                         TextureImages& textures) {
    Material out;
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    out.baseColor = baseColorFactor(ctx, pbr.baseColorFactor, label);
    out.baseColorTexture = textures.imageFor(pbr.baseColorTexture, label);
    out.alphaMask = m.alphaMode == "MASK";
    if (m.alphaMode == "BLEND") ctx.warn(label + " uses alphaMode BLEND, drawn as OPAQUE");
    out.alphaCutoff = std::isfinite(m.alphaCutoff) ? static_cast<float>(std::clamp(m.alphaCutoff, 0.0, 1.0)) : 0.5f;
    out.doubleSided = m.doubleSided;
    return out;
}

}  // namespace

void convertMaterials(LoadContext& ctx, const tinygltf::Model& model, Scene& scene) {
    TextureImages textures(ctx, model, scene);
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& m = model.materials[i];
        std::string label = "material " + std::to_string(i);
        if (!m.name.empty()) label += " ('" + m.name.substr(0, 60) + "')";
        scene.materials.push_back(convertMaterial(ctx, m, label, textures));
    }
    if (ctx.usesDefaultMaterial) scene.materials.push_back(Material{});
}

}  // namespace st::gltf
