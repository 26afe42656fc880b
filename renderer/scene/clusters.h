#pragma once
// Spatial clusters of a scene's triangles: the unit the passes cull and draw (issue 11 item 2).
// A scene of a few large meshes (a terrain and a town as one mesh each) cannot be culled per draw
// item, and a field of 100,000 tiny nodes cannot be drawn per item; clusters of at most a few
// hundred triangles of one material fix both. Built once at load, deterministically (the same
// clusters every run: the split order depends on the triangles alone). No GL.
//
// The scene's triangles are flattened to world space at load (scene.h), so there is no
// instancing left to keep: every node's triangles are its own.
#include "renderer/csm/geometry.h"
#include "renderer/scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st {

struct Cluster {
    std::uint32_t firstIndex = 0;  // into ClusteredScene::indices
    std::uint32_t indexCount = 0;
    int material = 0;              // as DrawItem::material (clusters never mix materials)
    csm::Aabb wsBounds;            // of its triangles
};

struct ClusteredScene {
    // The scene's triangles, reordered: clusters are contiguous and sorted by material, so the
    // visible clusters of one material merge into few index ranges.
    std::vector<std::uint32_t> indices;
    std::vector<Cluster> clusters;
    std::size_t triangleCount() const { return indices.size() / 3; }
};

inline constexpr int kClusterTriangles = 256;  // most triangles per cluster

// Every triangle of every draw item exactly once. Within one material, triangles are split at
// the median of their centroids along the longest axis of the centroids' bounds, recursively,
// until a part holds at most maxTriangles (ties broken by the triangle's index in the scene).
ClusteredScene buildClusters(const Scene& scene, int maxTriangles = kClusterTriangles);

}  // namespace st
