#include "renderer/render/frame_stats.h"

#include "renderer/render/pass_work_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace st {

std::string toJsonText(const FrameStats& s) {
    nlohmann::ordered_json j;
    j["width"] = s.width;
    j["height"] = s.height;
    j["sceneTriangles"] = s.sceneTriangles;
    j["splits"] = s.splits;
    j["splitRange"] = {s.splitBegin, s.splitEnd};
    auto& db = j["depthBounds"];
    db["mode"] = s.depthBounds.mode;
    db["reduced"] = s.depthBounds.reduced;
    if (s.depthBounds.seen) {
        db["seenNear"] = s.depthBounds.vsMin;
        db["seenFar"] = s.depthBounds.vsMax;
    } else {
        db["seenNear"] = db["seenFar"] = nullptr;  // nothing reduced, or only background seen
    }
    db["source"] = s.depthBounds.source;
    j["shadowMapBytes"] = s.shadowMapBytes;
    j["filterMapBytes"] = s.filterMapBytes;
    j["screenShadowBytes"] = s.screenShadowBytes;
    j["gpuShadowMs"] = s.gpuShadowMs;
    j["gpuFilterMs"] = s.gpuFilterMs;
    j["gpuScreenShadowMs"] = s.gpuScreenShadowMs;
    j["gpuScreenBlurMs"] = s.gpuScreenBlurMs;
    j["gpuMainMs"] = s.gpuMainMs;
    j["gpuDepthBoundsMs"] = s.gpuDepthBoundsMs;
    j["cpuMs"] = s.cpuMs;
    j["mainTriangles"] = s.mainTriangles;
    j["mainDraws"] = s.mainDraws;
    j["work"] = frameWorkJson(s.work);
    if (s.modelMs >= 0.0) {
        j["modelMs"] = s.modelMs;
        j["modelShadowMs"] = s.modelShadowMs;
        j["costProfile"] = s.costProfile;
    }
    auto& arr = j["cascades"] = nlohmann::ordered_json::array();
    for (const CascadeStats& c : s.cascades) {
        nlohmann::ordered_json e;
        e["vsNear"] = c.vsNear;
        e["vsFar"] = c.vsFar;
        e["lightBoxSize"] = {c.lsExtent.x, c.lsExtent.y, c.lsExtent.z};
        e["texelWorldSize"] = c.texelWorldSize;
        e["mapSize"] = c.mapSize;
        e["casterDraws"] = c.casterDraws;
        e["casterTriangles"] = c.casterTriangles;
        e["casterClusters"] = c.casterClusters;
        e["casterClustersTotal"] = c.casterClustersTotal;
        e["lowerBoundTriangles"] = c.lowerBoundTriangles;
        e["redrawn"] = c.redrawn;
        e["mapReason"] = c.mapReason;
        e["gpuMs"] = c.gpuMs;
        e["samplesFitted"] = c.samplesFitted;
        auto& z = e["zExtension"];
        if (std::isinf(c.zExtensionUsed)) z["used"] = "pancake";
        else z["used"] = c.zExtensionUsed;
        z["minimal"] = c.zExtensionMinimal;
        z["cuts"] = c.zExtensionCuts;
        arr.push_back(e);
    }
    j["warnings"] = s.warnings;
    return j.dump(2) + "\n";
}

}  // namespace st
