#include "renderer/scene/gltf_scene.h"
#include "renderer/scene/scene.h"

#include <algorithm>

namespace st {

Scene loadScene(const std::string& spec, const std::filesystem::path& baseDir, const SceneOptions& options) {
    const std::string prefix = "builtin:";
    if (spec.rfind(prefix, 0) == 0) return makeBuiltinScene(spec.substr(prefix.size()));
    std::filesystem::path file(spec);
    if (file.is_relative()) file = baseDir / file;
    Scene scene = loadGltfScene(file);
    if (options.ground) addGroundUnder(scene);
    return scene;
}

std::string sceneKey(const std::string& spec, const std::filesystem::path& baseDir, const SceneOptions& options) {
    if (spec.rfind("builtin:", 0) == 0) return spec;
    std::error_code ec;  // a path that cannot be resolved is still a key; loading it reports the error
    const auto path = std::filesystem::weakly_canonical(baseDir / spec, ec);
    return (ec ? (baseDir / spec).string() : path.string()) + (options.ground ? "|ground" : "");
}

void addGroundUnder(Scene& s) {
    finalizeBounds(s);
    const glm::vec3 lo = s.wsBounds.min, hi = s.wsBounds.max;
    const float halfWidth = 2.0f * std::max({hi.x - lo.x, hi.z - lo.z, 1e-3f});
    const glm::vec3 centre = 0.5f * (lo + hi);
    const int material = static_cast<int>(s.materials.size());
    s.materials.push_back(Material{.baseColor = {0.55f, 0.53f, 0.5f, 1.0f}});
    const std::size_t first = s.vertices.size();
    addGroundQuad(s, halfWidth, lo.y, material);
    for (std::size_t i = first; i < s.vertices.size(); ++i) s.vertices[i].position += glm::vec3(centre.x, 0, centre.z);
    finalizeBounds(s);
}

}  // namespace st
