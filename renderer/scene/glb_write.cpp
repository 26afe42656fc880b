#include "renderer/scene/glb_write.h"

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace st {
namespace {

using nlohmann::json;

void appendBytes(std::string& bin, const void* data, std::size_t bytes) { bin.append(static_cast<const char*>(data), bytes); }

void padTo4(std::string& s, char fill) {
    while (s.size() % 4 != 0) s.push_back(fill);
}

void appendWord(std::string& out, std::uint32_t v) { appendBytes(out, &v, 4); }

json glbMaterial(const Material& m) {
    json j = {{"pbrMetallicRoughness",
               {{"baseColorFactor", {m.baseColor.r, m.baseColor.g, m.baseColor.b, m.baseColor.a}},
                {"metallicFactor", 0.0},
                {"roughnessFactor", 1.0}}},
              {"doubleSided", m.doubleSided}};
    if (m.alphaMask) {
        j["alphaMode"] = "MASK";
        j["alphaCutoff"] = m.alphaCutoff;
    }
    return j;
}

}  // namespace

std::string glbOfDraws(const Scene& scene, std::size_t firstDraw) {
    // The vertices the draws use, renumbered in first-use order.
    std::unordered_map<std::uint32_t, std::uint32_t> remap;
    std::vector<std::uint32_t> used;
    std::vector<std::vector<std::uint32_t>> drawIndices;
    for (std::size_t d = firstDraw; d < scene.draws.size(); ++d) {
        const DrawItem& item = scene.draws[d];
        std::vector<std::uint32_t> idx;
        for (std::uint32_t k = 0; k < item.indexCount; ++k) {
            const std::uint32_t v = scene.indices[item.firstIndex + k];
            auto [it, added] = remap.try_emplace(v, static_cast<std::uint32_t>(used.size()));
            if (added) used.push_back(v);
            idx.push_back(it->second);
        }
        drawIndices.push_back(std::move(idx));
    }
    std::string bin;
    glm::vec3 lo(0.0f), hi(0.0f);
    for (std::size_t k = 0; k < used.size(); ++k) {
        const glm::vec3 p = scene.vertices[used[k]].position;
        lo = k == 0 ? p : glm::min(lo, p);
        hi = k == 0 ? p : glm::max(hi, p);
        appendBytes(bin, &p, sizeof p);
    }
    const std::size_t normalsAt = bin.size();
    for (std::uint32_t v : used) appendBytes(bin, &scene.vertices[v].normal, sizeof(glm::vec3));
    const auto count = used.size();
    json views = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", normalsAt}, {"target", 34962}},
                              {{"buffer", 0}, {"byteOffset", normalsAt}, {"byteLength", bin.size() - normalsAt}, {"target", 34962}}});
    json accessors = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"},
                                   {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}},
                                  {{"bufferView", 1}, {"componentType", 5126}, {"count", count}, {"type", "VEC3"}}});
    json primitives = json::array();
    json materials = json::array();
    std::unordered_map<int, int> materialIndex;
    for (std::size_t d = 0; d < drawIndices.size(); ++d) {
        const std::size_t at = bin.size();
        appendBytes(bin, drawIndices[d].data(), drawIndices[d].size() * 4);
        views.push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", drawIndices[d].size() * 4}, {"target", 34963}});
        accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", 5125}, {"count", drawIndices[d].size()},
                             {"type", "SCALAR"}});
        const int m = scene.draws[firstDraw + d].material;
        auto [it, added] = materialIndex.try_emplace(m, static_cast<int>(materials.size()));
        if (added) {
            const bool known = m >= 0 && m < static_cast<int>(scene.materials.size());
            materials.push_back(glbMaterial(known ? scene.materials[std::size_t(m)] : Material{}));
        }
        primitives.push_back({{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", accessors.size() - 1},
                              {"material", it->second}, {"mode", 4}});
    }
    padTo4(bin, '\0');
    const json gltf = {{"asset", {{"version", "2.0"}, {"generator", "shadowtune glb_write"}}},
                       {"scene", 0},
                       {"scenes", {{{"nodes", {0}}}}},
                       {"nodes", {{{"mesh", 0}, {"name", scene.name}}}},
                       {"meshes", {{{"primitives", primitives}}}},
                       {"materials", materials},
                       {"buffers", {{{"byteLength", bin.size()}}}},
                       {"bufferViews", views},
                       {"accessors", accessors}};
    std::string text = gltf.dump();
    padTo4(text, ' ');
    std::string out;
    appendWord(out, 0x46546C67u);  // "glTF"
    appendWord(out, 2u);
    appendWord(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    appendWord(out, static_cast<std::uint32_t>(text.size()));
    appendWord(out, 0x4E4F534Au);  // "JSON"
    out += text;
    appendWord(out, static_cast<std::uint32_t>(bin.size()));
    appendWord(out, 0x004E4942u);  // "BIN\0"
    out += bin;
    return out;
}

}  // namespace st
