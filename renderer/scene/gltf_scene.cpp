// loadGltf: parse (gltf_parse.cpp), materials, node walk, then the whole-scene checks.
#include "renderer/scene/gltf_detail.h"

#include <glm/common.hpp>

#include <array>
#include <iostream>
#include <system_error>

namespace st {

namespace {

namespace fs = std::filesystem;

gltf::LoadContext makeContext(const fs::path& file, const GltfLimits& limits) {
    gltf::LoadContext ctx;
    ctx.file = file;
    ctx.limits = limits;
    std::error_code ec;
    const fs::path absolute = fs::absolute(file, ec);
    ctx.sceneDir = fs::weakly_canonical(absolute.parent_path(), ec);
    if (ec) ctx.fail("its folder cannot be resolved: " + ec.message());
    return ctx;
}

void checkExtensions(gltf::LoadContext& ctx, const tinygltf::Model& model) {
    constexpr std::array<std::string_view, 3> compressed = {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                                            "KHR_meshopt_compression"};
    for (const std::string& ext : model.extensionsRequired) {
        for (std::string_view c : compressed) {
            if (ext == c) ctx.fail("requires " + ext + " (compressed geometry), which is not supported");
        }
        if (ext != "KHR_mesh_quantization") {
            ctx.warn("requires " + ext.substr(0, 80) + ", which is ignored: the scene may look wrong");
        }
    }
}

csm::Aabb sceneBounds(const Scene& scene) {
    csm::Aabb box = scene.draws.front().wsBounds;
    for (const DrawItem& d : scene.draws) {
        box.min = glm::min(box.min, d.wsBounds.min);
        box.max = glm::max(box.max, d.wsBounds.max);
    }
    return box;
}

void failWithoutTriangles(const gltf::LoadContext& ctx, const gltf::GeometryStats& stats) {
    std::string why = "no node of the scene instantiates a mesh";
    if (stats.meshInstances > 0 && stats.primitivesSkipped == 0) why = "its meshes have no primitives";
    if (stats.primitivesSkipped > 0) {
        why = std::to_string(stats.primitivesSkipped) + " primitive instance(s) skipped";
        if (!ctx.warnings.empty()) why += "; first: " + ctx.warnings.front();
    }
    ctx.fail("contains no triangles (" + why + ")");
}

}  // namespace

GltfLoadResult loadGltf(const fs::path& file, const GltfLimits& limits) {
    gltf::LoadContext ctx = makeContext(file, limits);
    const tinygltf::Model model = gltf::parseModel(ctx);
    checkExtensions(ctx, model);
    GltfLoadResult result;
    Scene& scene = result.scene;
    scene.name = file.stem().string();
    gltf::GeometryStats stats;
    gltf::appendSceneNodes(ctx, model, scene, stats);
    if (scene.draws.empty()) failWithoutTriangles(ctx, stats);
    gltf::convertMaterials(ctx, model, scene);
    scene.wsBounds = sceneBounds(scene);
    result.warnings = std::move(ctx.warnings);
    return result;
}

Scene loadGltfScene(const fs::path& file) {
    GltfLoadResult result = loadGltf(file);
    for (const std::string& warning : result.warnings) {
        std::cerr << "shadowtune: " << file.string() << ": warning: " << warning << '\n';
    }
    return std::move(result.scene);
}

}  // namespace st
