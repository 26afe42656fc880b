#pragma once
// What one frame reports: the derived figures the editor shows next to the knobs and headless
// replay writes beside each image.
#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace st {

struct CascadeStats {
    float vsNear = 0.0f;           // view depth range covered, metres
    float vsFar = 0.0f;
    glm::vec3 lsExtent{0.0f};      // light box size x, y, z (z = depth range), metres
    float texelWorldSize = 0.0f;   // metres per shadow texel
    // What the map holds (drawn this frame, or at its last redraw when cached):
    int casterDraws = 0;           // GL draw calls (one multi-draw per material of the clusters)
    std::size_t casterTriangles = 0;
    std::size_t casterClusters = 0;     // clusters submitted (renderer/scene/clusters.h)
    std::size_t casterClustersTotal = 0;// clusters in the scene
    // Triangles whose own light-space bounds meet the light box (extended toward the light):
    // what a perfect per-triangle box test would submit (docs/architecture.md#lower-bound-of-the-shadow-pass).
    std::size_t lowerBoundTriangles = 0;
    bool redrawn = true;           // this frame drew the map; false: the map from an earlier frame
    std::string mapReason;         // why it was redrawn or kept ("light matrix changed", "unchanged", ...)
    double gpuMs = 0.0;            // this cascade's depth pass
};

struct FrameStats {
    std::vector<float> splits;
    std::vector<CascadeStats> cascades;
    std::size_t shadowMapBytes = 0;
    double gpuShadowMs = 0.0;  // all cascades
    double gpuMainMs = 0.0;
    double cpuMs = 0.0;        // CPU time to plan and submit the frame
    std::size_t mainTriangles = 0;  // submitted by the main pass after frustum culling of clusters
    int mainDraws = 0;
    std::size_t sceneTriangles = 0;
    int width = 0;
    int height = 0;
};

std::string toJsonText(const FrameStats& s);  // pretty JSON, for the file beside each image

}  // namespace st
