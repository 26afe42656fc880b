#pragma once
// What one frame reports: the derived figures the editor shows next to the knobs and headless
// replay writes beside each image.
#include "renderer/render/pass_work.h"

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
    int mapSize = 0;               // texels per side of this cascade's map
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
    PassWork drawnWork;            // the work of its last redraw (this frame's, or the kept map's)
    bool samplesFitted = false;    // light box fitted to the visible samples it holds (fit "samples")
    // z-extension audit (renderer/csm/z_extension_audit.h), metres toward the sun beyond the slice:
    float zExtensionUsed = 0.0f;   // +inf with pancaking (casters clamp onto the near plane)
    float zExtensionMinimal = 0.0f;
    bool zExtensionCuts = false;   // the setting clips a caster that can shadow the slice
};

// The depth reduction of sample distribution shadow maps (renderer/csm/depth_bounds.h).
struct DepthBoundsStats {
    std::string mode = "off";      // cascades.depthBounds
    bool reduced = false;          // the frame reduced the camera's depth buffer
    bool seen = false;             // some pixel shows geometry
    float vsMin = 0.0f;            // nearest and farthest view depth seen, metres
    float vsMax = 0.0f;
    std::string source;            // whose depth buffer: "depth prepass, same frame" or "previous frame"
};

struct FrameStats {
    std::vector<float> splits;
    float splitBegin = 0.0f;   // the view-depth range the split scheme divided (fitted with depthBounds fit)
    float splitEnd = 0.0f;
    DepthBoundsStats depthBounds;
    std::vector<CascadeStats> cascades;
    std::size_t shadowMapBytes = 0;
    std::size_t filterMapBytes = 0;  // the filter's own maps (moment array and scratch; the screen-space targets), 0 if none
    std::size_t screenShadowBytes = 0;  // filter.screenSpace's targets (part of filterMapBytes)
    double gpuShadowMs = 0.0;  // all cascades
    double gpuFilterMs = 0.0;  // the filter's extra passes (moment maps and their blur; the screen-space path)
    double gpuScreenShadowMs = 0.0;  // filter.screenSpace: mask, downsample, blurs, upsample (part of gpuFilterMs)
    double gpuScreenBlurMs = 0.0;    // of which the downsample, blurs and upsample (the rest: the mask pass)
    double gpuMainMs = 0.0;
    double gpuDepthBoundsMs = 0.0;  // depth prepass and reduction (0 without them)
    double cpuMs = 0.0;        // CPU time to plan and submit the frame
    std::size_t mainTriangles = 0;  // submitted by the main pass after frustum culling of clusters
    // RenderOptions::shadeMain off and the same camera and size as the last frame's unshaded main
    // pass: it was not drawn again, and work.main is that pass's (Renderer::keptMain_).
    bool mainKept = false;
    // RenderOptions::shadeMain off and the same camera and size as the last depth prepass, with
    // nothing drawn into the target's depth since: it was not drawn again, and its counted work
    // is that prepass's (Renderer::keptPrepass_); the reduction runs as always.
    bool prepassKept = false;
    int mainDraws = 0;
    int mainRanges = 0;        // draw commands: the index ranges of mainDraws' multi-draws (naive: = mainDraws)
    FrameWork work;            // counted work per pass (pass_work.h), filled by Renderer::render
    std::size_t sceneTriangles = 0;
    int width = 0;
    int height = 0;
    // Filled by the commands, not by Renderer::render: wasted maps and cut casters, each with
    // the likely fix (metrics/map_warnings.h).
    std::vector<std::string> warnings;
    // Filled by the commands too: the cost model's milliseconds for `work` (metrics/cost_model.h),
    // all passes and the shadow pass, and the profile's name; modelMs < 0 when not modelled.
    double modelMs = -1.0;
    double modelShadowMs = -1.0;
    std::string costProfile;
};

std::string toJsonText(const FrameStats& s);  // pretty JSON, for the file beside each image

}  // namespace st
