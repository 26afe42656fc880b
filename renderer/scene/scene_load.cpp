#include "renderer/scene/gltf_scene.h"
#include "renderer/scene/scene.h"

namespace st {

Scene loadScene(const std::string& spec, const std::filesystem::path& baseDir) {
    const std::string prefix = "builtin:";
    if (spec.rfind(prefix, 0) == 0) return makeBuiltinScene(spec.substr(prefix.size()));
    std::filesystem::path file(spec);
    if (file.is_relative()) file = baseDir / file;
    return loadGltfScene(file);
}

}  // namespace st
