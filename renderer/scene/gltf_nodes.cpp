// The node hierarchy: which roots, local transforms (matrix or TRS), and the walk down to meshes.
#include "renderer/scene/gltf_detail.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace st::gltf {

namespace {

std::string nodeLabel(const tinygltf::Model& model, int index) {
    std::string label = "node " + std::to_string(index);
    const std::string& name = model.nodes[static_cast<std::size_t>(index)].name;
    if (!name.empty()) label += " ('" + name.substr(0, 60) + "')";
    return label;
}

void checkSize(const LoadContext& ctx, const std::vector<double>& v, std::size_t expected, const char* what,
               const std::string& label) {
    if (!v.empty() && v.size() != expected) {
        ctx.fail(label + " '" + what + "' has " + std::to_string(v.size()) + " numbers, not " + std::to_string(expected));
    }
}

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

glm::dmat4 localTransform(LoadContext& ctx, const tinygltf::Node& node, const std::string& label) {
    glm::dmat4 m(1.0);
    checkSize(ctx, node.matrix, 16, "matrix", label);
    checkSize(ctx, node.translation, 3, "translation", label);
    checkSize(ctx, node.rotation, 4, "rotation", label);
    checkSize(ctx, node.scale, 3, "scale", label);
    if (!node.matrix.empty()) {
        m = glm::make_mat4(node.matrix.data());  // glTF matrices are column-major, like glm
    } else {
        if (!node.translation.empty()) m = glm::translate(m, glm::make_vec3(node.translation.data()));
        if (!node.rotation.empty()) {
            const std::vector<double>& r = node.rotation;  // glTF order x, y, z, w
            const glm::dquat q(r[3], r[0], r[1], r[2]);
            const double length = glm::length(q);
            if (!(length > 1e-12) || !std::isfinite(length)) ctx.fail(label + " has a zero or non-finite rotation");
            m = m * glm::mat4_cast(q / length);
        }
        if (!node.scale.empty()) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    }
    if (!allFinite(m)) ctx.fail(label + " has a non-finite transform");
    return m;
}

MeshInstance makeInstance(const glm::dmat4& world, std::string label) {
    MeshInstance instance;
    const glm::dmat3 linear(world);
    const double det = glm::determinant(linear);
    const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    instance.singular = !(std::abs(det) > 1e-9 * scale) || !std::isfinite(det);
    instance.flipWinding = !instance.singular && det < 0.0;
    if (!instance.singular) instance.wsNormalFromLocal = glm::mat3(glm::transpose(glm::inverse(linear)));
    instance.wsFromLocal = glm::mat4(world);
    instance.nodeLabel = std::move(label);
    return instance;
}

class NodeWalker {
public:
    NodeWalker(LoadContext& ctx, const tinygltf::Model& model, Scene& scene, GeometryStats& stats)
        : ctx_(ctx), model_(model), scene_(scene), stats_(stats), onPath_(model.nodes.size(), false) {}

    void visit(int index, const glm::dmat4& parent, int depth, const std::string& referrer) {
        if (index < 0 || index >= static_cast<int>(model_.nodes.size())) {
            ctx_.fail(referrer + " refers to node " + std::to_string(index) + ", but the file has " +
                      std::to_string(model_.nodes.size()) + " nodes");
        }
        const std::string label = nodeLabel(model_, index);
        if (onPath_[static_cast<std::size_t>(index)]) ctx_.fail(label + " is its own ancestor (a cycle in 'children')");
        if (depth > ctx_.limits.maxNodeDepth) {
            ctx_.fail(label + " is deeper than " + std::to_string(ctx_.limits.maxNodeDepth) +
                      " levels (GltfLimits::maxNodeDepth)");
        }
        if (++visits_ > ctx_.limits.maxNodeInstances) {
            ctx_.fail("the node hierarchy instantiates more than " + std::to_string(ctx_.limits.maxNodeInstances) +
                      " nodes (GltfLimits::maxNodeInstances)");
        }
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
        const glm::dmat4 world = parent * localTransform(ctx_, node, label);
        if (node.mesh >= 0) appendMesh(node.mesh, makeInstance(world, label));
        onPath_[static_cast<std::size_t>(index)] = true;
        for (int child : node.children) visit(child, world, depth + 1, label);
        onPath_[static_cast<std::size_t>(index)] = false;
    }

private:
    void appendMesh(int mesh, const MeshInstance& instance) {
        if (mesh >= static_cast<int>(model_.meshes.size())) {
            ctx_.fail(instance.nodeLabel + " refers to mesh " + std::to_string(mesh) + ", but the file has " +
                      std::to_string(model_.meshes.size()) + " meshes");
        }
        ++stats_.meshInstances;
        const std::size_t primitives = model_.meshes[static_cast<std::size_t>(mesh)].primitives.size();
        for (std::size_t p = 0; p < primitives; ++p) {
            appendPrimitive(ctx_, model_, mesh, static_cast<int>(p), instance, scene_, stats_);
        }
    }

    LoadContext& ctx_;
    const tinygltf::Model& model_;
    Scene& scene_;
    GeometryStats& stats_;
    std::vector<bool> onPath_;
    std::uint64_t visits_ = 0;
};

// The default scene, else scene 0, else every node that is nobody's child.
std::vector<int> rootNodes(LoadContext& ctx, const tinygltf::Model& model, std::string& referrer) {
    int chosen = model.defaultScene;
    if (chosen >= static_cast<int>(model.scenes.size())) {
        ctx.warn("the default scene " + std::to_string(chosen) + " does not exist: scene 0 used");
        chosen = -1;
    }
    if (chosen < 0 && !model.scenes.empty()) chosen = 0;
    if (chosen >= 0) {
        referrer = "scene " + std::to_string(chosen);
        return model.scenes[static_cast<std::size_t>(chosen)].nodes;
    }
    referrer = "the root node list";
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
        for (int child : node.children) {
            if (child >= 0 && child < static_cast<int>(isChild.size())) isChild[static_cast<std::size_t>(child)] = true;
        }
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < isChild.size(); ++i) {
        if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
}

}  // namespace

void appendSceneNodes(LoadContext& ctx, const tinygltf::Model& model, Scene& scene, GeometryStats& stats) {
    std::string referrer;
    const std::vector<int> roots = rootNodes(ctx, model, referrer);
    NodeWalker walker(ctx, model, scene, stats);
    for (int root : roots) walker.visit(root, glm::dmat4(1.0), 0, referrer);
}

}  // namespace st::gltf
