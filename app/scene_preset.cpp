#include "app/scene_preset.h"

#include "renderer/scene/scene.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::app {
namespace fs = std::filesystem;
namespace {

// The scene has a floor when triangles facing up at its very bottom (the lowest 5 % of its height)
// cover a quarter of its footprint: then its own ground takes the shadows, else a ground is added
// under it (a ship's deck or a room's upper floors do not count).
bool hasFloor(const Scene& s) {
    const glm::vec3 lo = s.wsBounds.min, hi = s.wsBounds.max;
    const float footprint = std::max((hi.x - lo.x) * (hi.z - lo.z), 1e-6f);
    const float bottom = lo.y + 0.05f * std::max(hi.y - lo.y, 1e-3f);
    double up = 0.0;
    for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
        const glm::vec3 a = s.vertices[s.indices[t]].position, b = s.vertices[s.indices[t + 1]].position,
                        c = s.vertices[s.indices[t + 2]].position;
        const glm::vec3 n = glm::cross(b - a, c - a);  // length: twice the area
        const float len = glm::length(n);
        if (len <= 0.0f || n.y < 0.9f * len) continue;
        if (std::max({a.y, b.y, c.y}) <= bottom) up += 0.5 * double(n.y);
    }
    return up >= 0.25 * double(footprint);
}

// Where the scene's detail is: the vertices are counted on a 32 x 32 grid over its footprint and
// the cells holding at least a quarter of the densest cell's count are framed. A town on a 2 km
// terrain or a palm tree on an island in a 64 m sea is framed, not the terrain or the sea, whose
// vertices are spread thin.
csm::Aabb detailBounds(const Scene& s) {
    constexpr int kGrid = 32;
    const glm::vec3 lo = s.wsBounds.min, hi = s.wsBounds.max;
    const glm::vec2 size = glm::max(glm::vec2(hi.x - lo.x, hi.z - lo.z), glm::vec2(1e-6f));
    const auto cellOf = [&](const glm::vec3& p) {
        const int x = std::clamp(int((p.x - lo.x) / size.x * kGrid), 0, kGrid - 1);
        const int z = std::clamp(int((p.z - lo.z) / size.y * kGrid), 0, kGrid - 1);
        return z * kGrid + x;
    };
    std::vector<std::size_t> count(kGrid * kGrid, 0);
    for (const Vertex& v : s.vertices) ++count[std::size_t(cellOf(v.position))];
    const std::size_t peak = *std::max_element(count.begin(), count.end());
    csm::Aabb b;
    bool any = false;
    for (const Vertex& v : s.vertices) {
        if (4 * count[std::size_t(cellOf(v.position))] < peak) continue;
        b.min = any ? glm::min(b.min, v.position) : v.position;
        b.max = any ? glm::max(b.max, v.position) : v.position;
        any = true;
    }
    return any ? b : s.wsBounds;
}

}  // namespace

bool isGltfPath(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".gltf" || ext == ".glb";
}

Settings presetForScene(const fs::path& gltf, const fs::path& presetDir) {
    const fs::path absolute = fs::absolute(gltf).lexically_normal();
    const Scene scene = loadScene(absolute.string(), ".");
    if (scene.triangleCount() == 0) throw std::runtime_error(gltf.string() + ": the glTF holds no triangles to shadow");
    Settings s;
    s.scene = presetDir.empty() ? std::string()
                                : absolute.lexically_relative(fs::absolute(presetDir).lexically_normal()).generic_string();
    if (s.scene.empty()) s.scene = absolute.generic_string();
    s.notes = "made by shadowtune init from " + gltf.filename().string() +
              ": the camera frames the scene's bounds, the cascades span it";
    s.ground = !hasFloor(scene);
    const csm::Aabb detail = detailBounds(scene);
    const glm::vec3 lo = detail.min, hi = detail.max;
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    // From 30 deg to the side and 25 deg above, far enough that the bounding sphere fills the view.
    const float az = glm::radians(30.0f), el = glm::radians(25.0f);
    const glm::vec3 dir(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    const float distance = 1.1f * radius / std::sin(glm::radians(0.5f * s.camera.fovY));
    s.camera.position = centre + dir * distance;
    s.camera.target = centre;
    s.camera.nearPlane = std::max(1e-3f, 0.01f * distance);
    // The ground reaches 2 scene widths out; the far plane takes it, the shadows end past the scene.
    // The far plane takes the whole scene (and the ground, 2 scene widths out); the shadows end past
    // the detail.
    const float whole = 0.5f * glm::length(scene.wsBounds.max - scene.wsBounds.min);
    const float reach = s.ground ? 4.0f * whole : whole;
    s.camera.farPlane = distance + reach + glm::length(centre - 0.5f * (scene.wsBounds.min + scene.wsBounds.max));
    s.cascades.count = 4;
    s.cascades.lambda = 0.75f;
    s.cascades.shadowDistance = std::min(s.camera.farPlane, distance + 1.5f * radius);
    s.cascades.zExtension = ZExtension::SceneBounds;
    s.bias.constant = 0.002f * radius;  // metres: the default 2 cm belongs to a 10 m scene
    return s;
}

}  // namespace st::app
