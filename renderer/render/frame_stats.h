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
    int casterDraws = 0;           // draw calls after culling against the light box
    std::size_t casterTriangles = 0;
    double gpuMs = 0.0;            // this cascade's depth pass
};

struct FrameStats {
    std::vector<float> splits;
    std::vector<CascadeStats> cascades;
    std::size_t shadowMapBytes = 0;
    std::size_t filterMapBytes = 0;  // the filter's own maps (moment array and scratch), 0 if none
    double gpuShadowMs = 0.0;  // all cascades
    double gpuFilterMs = 0.0;  // the filter's extra passes (moment maps and their blur)
    double gpuMainMs = 0.0;
    double cpuMs = 0.0;        // CPU time to plan and submit the frame
    std::size_t sceneTriangles = 0;
    int width = 0;
    int height = 0;
};

std::string toJsonText(const FrameStats& s);  // pretty JSON, for the file beside each image

}  // namespace st
