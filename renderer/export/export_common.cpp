#include "renderer/export/export_common.h"

#include "renderer/csm/cascade_plan.h"
#include "renderer/settings/number_text.h"

#include <cmath>
#include <cstdio>

namespace st::xport {

PresetFacts presetFacts(const Settings& s) {
    Settings flat = s;
    flat.cascades.zExtension = ZExtension::None;  // x,y texel size is independent of z
    const float aspect = float(s.output.width) / float(s.output.height);
    const csm::CascadePlan plan = csm::planCascades(flat, aspect, csm::Aabb{});
    PresetFacts f;
    f.splits = plan.splits;
    f.nearPlane = s.camera.nearPlane;
    f.end = plan.splits.back();
    for (const csm::CascadeFit& c : plan.cascades) f.texel.push_back(c.texelWorldSize);
    return f;
}

std::vector<double> fractionsOfRange(const PresetFacts& f) {
    std::vector<double> out;
    for (size_t i = 1; i + 1 < f.splits.size(); ++i)
        out.push_back(round6((double(f.splits[i]) - f.nearPlane) / (double(f.end) - f.nearPlane)));
    return out;
}

std::vector<double> fractionsOfEnd(const PresetFacts& f) {
    std::vector<double> out;
    for (size_t i = 1; i + 1 < f.splits.size(); ++i) out.push_back(round6(double(f.splits[i]) / f.end));
    return out;
}

double round6(double v) {
    if (v == 0.0 || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, 5 - std::floor(std::log10(std::fabs(v))));
    return std::round(v * scale) / scale;
}

nlohmann::json numbers(const std::vector<double>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (double x : v) a.push_back(x);
    return a;
}

std::string texelNote(const PresetFacts& f) {
    return formatNumber(round6(f.texel.front())) + " m (cascade 0 as shadowtune fits it in this preset)";
}

}  // namespace st::xport
