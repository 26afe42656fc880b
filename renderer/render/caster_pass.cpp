// The culled, batched draws of the shadow and main passes and the cascade map cache (issue 11
// items 2 and 3), and the naive path the benchmarks compare them with.
#include "renderer/csm/caster_culling.h"
#include "renderer/csm/culling.h"
#include "renderer/render/renderer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace st {
namespace {

// A cascade's view for its casters: its matrix, its map's texel grid, and the casters' own normal
// offset (bias.normalOffsetSide caster-sin: moved into their surface in shadow_depth.vert).
gpu_if::ViewBlock casterViewBlockFor(const Settings& s, const glm::mat4& viewProj, int size, int subpixelSteps) {
    gpu_if::ViewBlock v = viewBlockOf(viewProj, size, size, subpixelSteps);
    v.casterNormalOffset = casterNormalOffset(s.bias);
    return v;
}

// Triangles of cluster k whose own light-space bounds meet the light box.
std::size_t trianglesMeetingBox(const Scene& scene, const ClusteredScene& cs, const Cluster& k,
                                const csm::CascadeFit& fit, bool pancake) {
    std::size_t n = 0;
    for (std::uint32_t t = k.firstIndex; t + 3 <= k.firstIndex + k.indexCount; t += 3) {
        csm::Aabb b;
        for (std::uint32_t v = 0; v < 3; ++v) {
            const glm::vec3 p(fit.lsView * glm::vec4(scene.vertices[cs.indices[t + v]].position, 1.0f));
            b.min = v == 0 ? p : glm::min(b.min, p);
            b.max = v == 0 ? p : glm::max(b.max, p);
        }
        n += csm::lsBoundsMeetBox(b, fit.lsBox, pancake);
    }
    return n;
}

// A redrawn map: its tile cleared and rasterised into (every texel once, D32F), by `commands` draws.
PassWork mapWork(int size, std::size_t commands) {
    PassWork w;
    w.draws = commands;
    w.texelsCleared = std::uint64_t(size) * std::uint64_t(size);
    w.bytesWritten = 4 * w.texelsCleared;
    return w;
}

}  // namespace

// Both: culling off (thin and open casters cast from both sides). Back or front: the other face
// culled on single-sided materials only, as engines do (three.js WebGLShadowMap.js: a DoubleSide
// material casts with both).
GLenum casterCullFace(CasterFaces faces) {
    return faces == CasterFaces::Back ? GL_FRONT : faces == CasterFaces::Front ? GL_BACK : GL_NONE;
}

FaceCulling casterCulling(CasterFaces faces) {
    return faces == CasterFaces::Both ? FaceCulling::Keep : FaceCulling::PerMaterial;
}

void Renderer::cascadeCasters(const Settings& s, int i, const gpu::PassState& state, CascadeStats& cs,
                              PassWork& work) {
    const bool pancake = s.cascades.zExtension == ZExtension::Pancake;
    const csm::CascadeFit fit = plan_.cascades[std::size_t(i)];
    const csm::CasterVolume volume = csm::casterVolume(s, plan_.camera, plan_.splits, i, fit);
    const ClusteredScene& clustered = scene_.clustered();
    const std::vector<Cluster>& clusters = clustered.clusters;
    batches_.clear();
    std::vector<std::size_t> inBox;  // clusters the box test alone keeps: the lower bound's candidates
    for (std::size_t k = 0; k < clusters.size(); ++k) {
        if (!csm::lsBoundsMeetBox(csm::transformAabb(fit.lsView, clusters[k].wsBounds), fit.lsBox, pancake)) continue;
        inBox.push_back(k);
        if (csm::casterMayShadow(clusters[k].wsBounds, volume)) batches_.add(clusters, k);
    }
    const CascadeMapKey key{fit.viewProj, pancake, batches_.hash(), shadowMaps_.cascades(), shadowMaps_.tile(i).size,
                            int(s.cascades.casterFaces), options_.subpixelSteps,
                            casterNormalOffset(s.bias)};
    const CascadeDecision d = cache_.decide(i, key);
    if (held_.size() < std::size_t(s.cascades.count)) held_.resize(std::size_t(s.cascades.count));
    CascadeStats& held = held_[std::size_t(i)];
    if (d.redraw) {
        shadowMaps_.beginCascade(i, state);  // its layer or tile: viewport, scissor, cleared
        const int size = shadowMaps_.tile(i).size;
        viewBlock_.upload(casterViewBlockFor(s, fit.viewProj, size, options_.subpixelSteps));
        scene_.drawDepthBatches(batches_, casterCulling(s.cascades.casterFaces), depthPrograms());
        cache_.drawn(i, key, fit);
        work = mapWork(shadowMaps_.tile(i).size, batches_.rangeCount());
        held = CascadeStats{};
        held.casterDraws = int(batches_.batches().size());
        held.casterTriangles = batches_.triangleCount();
        held.casterClusters = batches_.clusterCount();
        if (options_.lowerBound)
            for (std::size_t k : inBox)
                held.lowerBoundTriangles += trianglesMeetingBox(scene_.scene(), clustered, clusters[k], fit, pancake);
    } else {
        // The map keeps what it was drawn with: sample it through that fit (only an update
        // interval makes it differ from this frame's), over this frame's depth range.
        csm::CascadeFit kept = cache_.heldFit(i);
        kept.vsNear = fit.vsNear;
        kept.vsFar = fit.vsFar;
        plan_.cascades[std::size_t(i)] = kept;
    }
    cs.casterDraws = held.casterDraws;
    cs.casterTriangles = held.casterTriangles;
    cs.casterClusters = held.casterClusters;
    cs.lowerBoundTriangles = held.lowerBoundTriangles;
    cs.casterClustersTotal = clusters.size();
    cs.redrawn = d.redraw;
    cs.mapReason = d.reason;
}

void Renderer::naiveCascadeCasters(const Settings& s, int i, const gpu::PassState& state, CascadeStats& cs,
                                   PassWork& work) {
    const bool pancake = s.cascades.zExtension == ZExtension::Pancake;
    const csm::CascadeFit& fit = plan_.cascades[std::size_t(i)];
    shadowMaps_.beginCascade(i, state);
    const int size = shadowMaps_.tile(i).size;
    viewBlock_.upload(casterViewBlockFor(s, fit.viewProj, size, options_.subpixelSteps));
    for (const DrawItem& item : scene_.scene().draws) {
        if (!csm::casterNeeded(item.wsBounds, fit, pancake)) continue;
        scene_.draw(item, casterCulling(s.cascades.casterFaces));
        ++cs.casterDraws;
        cs.casterTriangles += item.indexCount / 3;
    }
    cs.redrawn = true;
    cs.mapReason = "naive: every map every frame";
    work = mapWork(shadowMaps_.tile(i).size, std::size_t(cs.casterDraws));
}

void Renderer::drawVisible(const glm::mat4& viewProj, const DepthPrograms* depth) {
    mainTriangles_ = 0;
    mainDraws_ = 0;
    mainRanges_ = 0;
    if (options_.naive) {
        scene_.bindGeometry();
        for (const DrawItem& item : scene_.scene().draws) {
            scene_.draw(item, FaceCulling::PerMaterial);
            mainTriangles_ += item.indexCount / 3;
            ++mainDraws_;
            ++mainRanges_;
        }
        visibleCommands_ = std::uint64_t(mainDraws_);
        return;
    }
    const auto planes = csm::frustumPlanes(viewProj);
    const std::vector<Cluster>& clusters = scene_.clustered().clusters;
    // Front to back within each material: llvmpipe shades every fragment that passes the depth
    // test when drawn, so the order of the clusters, not their count, sets the shading work.
    // The build order follows the split tree, front to back only from its low corner
    // (docs/architecture.md, "Lower bound of the shadow pass"). Clip z before the divide grows
    // with view depth for perspective and orthographic cameras alike; the index breaks ties.
    struct Visible {
        int material;
        float depth;
        std::uint32_t index;
    };
    std::vector<Visible> visible;
    const glm::vec4 depthRow(viewProj[0][2], viewProj[1][2], viewProj[2][2], viewProj[3][2]);
    for (std::size_t k = 0; k < clusters.size(); ++k) {
        if (!csm::aabbInFrustum(clusters[k].wsBounds, planes)) continue;
        const glm::vec3 centre = 0.5f * (clusters[k].wsBounds.min + clusters[k].wsBounds.max);
        visible.push_back({clusters[k].material, glm::dot(depthRow, glm::vec4(centre, 1.0f)), std::uint32_t(k)});
    }
    std::sort(visible.begin(), visible.end(), [](const Visible& a, const Visible& b) {
        if (a.material != b.material) return a.material < b.material;
        if (a.depth != b.depth) return a.depth < b.depth;
        return a.index < b.index;
    });
    batches_.clear();
    for (const Visible& v : visible) batches_.add(clusters, v.index);
    scene_.bindClusteredGeometry();
    if (depth) scene_.drawDepthBatches(batches_, FaceCulling::PerMaterial, *depth);
    else scene_.drawBatches(batches_, FaceCulling::PerMaterial);
    mainTriangles_ = batches_.triangleCount();
    mainDraws_ = int(batches_.batches().size());
    visibleCommands_ = batches_.rangeCount();
    mainRanges_ = int(batches_.rangeCount());
}

}  // namespace st
