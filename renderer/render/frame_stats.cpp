#include "renderer/render/frame_stats.h"

#include <nlohmann/json.hpp>

namespace st {

std::string toJsonText(const FrameStats& s) {
    nlohmann::ordered_json j;
    j["width"] = s.width;
    j["height"] = s.height;
    j["sceneTriangles"] = s.sceneTriangles;
    j["splits"] = s.splits;
    j["shadowMapBytes"] = s.shadowMapBytes;
    j["filterMapBytes"] = s.filterMapBytes;
    j["gpuShadowMs"] = s.gpuShadowMs;
    j["gpuFilterMs"] = s.gpuFilterMs;
    j["gpuMainMs"] = s.gpuMainMs;
    j["cpuMs"] = s.cpuMs;
    auto& arr = j["cascades"] = nlohmann::ordered_json::array();
    for (const CascadeStats& c : s.cascades) {
        nlohmann::ordered_json e;
        e["vsNear"] = c.vsNear;
        e["vsFar"] = c.vsFar;
        e["lightBoxSize"] = {c.lsExtent.x, c.lsExtent.y, c.lsExtent.z};
        e["texelWorldSize"] = c.texelWorldSize;
        e["casterDraws"] = c.casterDraws;
        e["casterTriangles"] = c.casterTriangles;
        e["gpuMs"] = c.gpuMs;
        arr.push_back(e);
    }
    return j.dump(2) + "\n";
}

}  // namespace st
