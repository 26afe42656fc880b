#include "renderer/render/pass_work_json.h"

namespace st {

nlohmann::ordered_json passWorkJson(const PassWork& w) {
    return {{"draws", w.draws},
            {"vertices", w.vertices},
            {"primitives", w.primitives},
            {"clippedPrimitives", w.clippedPrimitives},
            {"fragments", w.fragments},
            {"samplesPassed", w.samplesPassed},
            {"computeInvocations", w.computeInvocations},
            {"texelsCleared", w.texelsCleared},
            {"filterTaps", w.filterTaps},
            {"bytesRead", w.bytesRead},
            {"bytesWritten", w.bytesWritten}};
}

nlohmann::ordered_json frameWorkJson(const FrameWork& w) {
    nlohmann::ordered_json j;
    j["shadow"] = passWorkJson(w.shadow);
    auto& cascades = j["cascades"] = nlohmann::ordered_json::array();
    for (const PassWork& c : w.cascades) cascades.push_back(passWorkJson(c));
    j["main"] = passWorkJson(w.main);
    j["filter"] = passWorkJson(w.filter);
    j["depthBounds"] = passWorkJson(w.depthBounds);
    return j;
}

}  // namespace st
