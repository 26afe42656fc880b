#include "renderer/scene/clusters.h"

#include <glm/common.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

namespace st {
namespace {

struct Tri {
    std::uint32_t index;  // first index of the triangle in Scene::indices (unique: the tie-break)
    glm::vec3 centroid;
};

csm::Aabb emptyBox() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    return {glm::vec3(inf), glm::vec3(-inf)};
}

class Builder {
public:
    Builder(const Scene& scene, int material, std::size_t maxTriangles, ClusteredScene& out)
        : scene_(scene), material_(material), max_(maxTriangles), out_(out) {}

    // Splits [first, last) of tris, appending leaves in order (left part first): a depth-first
    // order, so neighbouring clusters are near each other and merge into longer index ranges.
    void split(std::vector<Tri>& tris, std::size_t first, std::size_t last) {
        if (last - first <= max_) {
            emit(tris, first, last);
            return;
        }
        csm::Aabb c = emptyBox();
        for (std::size_t i = first; i < last; ++i) {
            c.min = glm::min(c.min, tris[i].centroid);
            c.max = glm::max(c.max, tris[i].centroid);
        }
        const glm::vec3 e = c.extent();
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        const std::size_t mid = first + (last - first) / 2;
        // A strict total order (centroid, then scene index), so nth_element's result is one
        // partition whatever the library's algorithm.
        std::nth_element(tris.begin() + std::ptrdiff_t(first), tris.begin() + std::ptrdiff_t(mid),
                         tris.begin() + std::ptrdiff_t(last), [axis](const Tri& a, const Tri& b) {
                             if (a.centroid[axis] != b.centroid[axis]) return a.centroid[axis] < b.centroid[axis];
                             return a.index < b.index;
                         });
        split(tris, first, mid);
        split(tris, mid, last);
    }

private:
    void emit(std::vector<Tri>& tris, std::size_t first, std::size_t last) {
        // Scene order inside a cluster: the leaf's content is a set, its order then is fixed too.
        std::sort(tris.begin() + std::ptrdiff_t(first), tris.begin() + std::ptrdiff_t(last),
                  [](const Tri& a, const Tri& b) { return a.index < b.index; });
        Cluster k;
        k.firstIndex = static_cast<std::uint32_t>(out_.indices.size());
        k.material = material_;
        k.wsBounds = emptyBox();
        for (std::size_t i = first; i < last; ++i) {
            for (std::uint32_t v = 0; v < 3; ++v) {
                const std::uint32_t vi = scene_.indices[tris[i].index + v];
                out_.indices.push_back(vi);
                const glm::vec3 p = scene_.vertices[vi].position;
                k.wsBounds.min = glm::min(k.wsBounds.min, p);
                k.wsBounds.max = glm::max(k.wsBounds.max, p);
            }
        }
        k.indexCount = static_cast<std::uint32_t>(out_.indices.size()) - k.firstIndex;
        out_.clusters.push_back(k);
    }

    const Scene& scene_;
    int material_;
    std::size_t max_;
    ClusteredScene& out_;
};

}  // namespace

ClusteredScene buildClusters(const Scene& scene, int maxTriangles) {
    if (maxTriangles < 1) throw std::invalid_argument("buildClusters: maxTriangles must be >= 1");
    // Triangles by material, in scene order within each (std::map: materials in ascending order).
    std::map<int, std::vector<Tri>> byMaterial;
    for (const DrawItem& d : scene.draws) {
        std::vector<Tri>& tris = byMaterial[d.material];
        for (std::uint32_t i = d.firstIndex; i + 3 <= d.firstIndex + d.indexCount; i += 3) {
            const glm::vec3 a = scene.vertices[scene.indices[i]].position;
            const glm::vec3 b = scene.vertices[scene.indices[i + 1]].position;
            const glm::vec3 c = scene.vertices[scene.indices[i + 2]].position;
            tris.push_back({i, (a + b + c) / 3.0f});
        }
    }
    ClusteredScene out;
    out.indices.reserve(scene.indices.size());
    for (auto& [material, tris] : byMaterial) {
        if (tris.empty()) continue;
        Builder(scene, material, static_cast<std::size_t>(maxTriangles), out).split(tris, 0, tris.size());
    }
    return out;
}

}  // namespace st
