#include "sweep/sweep_results.h"

#include "renderer/settings/settings_json.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace st::sweep {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double pct(double share) { return 100.0 * share; }

std::string fingerprintOf(const SweepSpec& spec, const std::vector<Point>& points) {
    std::string text;
    for (const Axis& a : spec.axes) text += std::string(a.field->path) + ";";
    for (const Point& p : points) text += p.id + ",";
    return fnv1aHex(text);
}

// JSON has no NaN: a figure that does not apply is written as null.
nlohmann::ordered_json figureJson(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); }
}  // namespace

double PointResult::figure(const std::string& key) const {
    for (const auto& [k, v] : figures)
        if (k == key) return v;
    return kNaN;
}

Figures figuresOf(const metrics::PresetMeasurement& m) {
    const metrics::ErrorCounts& a = m.accuracy.all;
    Figures f = {
        {"misclassified_pct", pct(a.share(a.misclassified()))},
        {"false_shadow_pct", pct(a.share(a.falseShadow()))},
        {"false_light_pct", pct(a.share(a.falseLight()))},
        {"edge_pct", pct(a.share(a.falseShadowEdge + a.falseLightEdge))},
        {"gross_pct", pct(a.share(a.gross()))},
        {"gross_px", double(a.gross())},
        {"filtered_error", a.filteredError()},
        {"receivers_px", double(a.receivers)},
        {"density_median_px_per_texel", m.density.all.median},
        {"density_p90_px_per_texel", m.density.all.p90},
        {"density_p95_px_per_texel", m.density.all.p95},
        {"aliased_pct", pct(m.density.all.aliasingShare)},
        {"flicker_F_pct", m.flicker ? pct(m.flicker->flipRate) : kNaN},
    };
    // Against the soft truth of the sun's disc (metrics/soft_accuracy.h).
    const metrics::ArtifactCounts& k = m.soft.all;
    f.push_back({"soft_filtered_error", k.filteredError()});
    f.push_back({"acne_pct", pct(k.share(k.acne))});
    f.push_back({"light_bleeding_pct", pct(k.share(k.lightBleeding))});
    f.push_back({"peter_panning_pct", pct(k.share(k.peterPanning))});
    f.push_back({"missing_caster_pct", pct(k.share(k.missingCaster))});
    f.push_back({"soft_edge_pct", pct(k.share(k.edge))});
    f.push_back({"penumbra_width_error_px", m.soft.penumbra.errorPx()});
    f.push_back({"penumbra_width_abs_error_px", std::abs(m.soft.penumbra.errorPx())});
    const bool cost = m.cost.has_value();
    f.push_back({"gpu_shadow_ms", cost ? m.cost->gpuShadowMs : kNaN});
    f.push_back({"gpu_main_ms", cost ? m.cost->gpuMainMs : kNaN});
    f.push_back({"gpu_ms", cost ? m.cost->gpuShadowMs + m.cost->gpuFilterMs + m.cost->gpuMainMs : kNaN});
    f.push_back({"cpu_ms", cost ? m.cost->cpuMs : kNaN});
    f.push_back({"shadow_map_mib",
                 cost ? double(m.cost->shadowMapBytes + m.cost->filterMapBytes) / (1024.0 * 1024.0) : kNaN});
    f.push_back({"caster_triangles", cost ? double(m.cost->triangles) : kNaN});
    f.push_back({"caster_draws", cost ? double(m.cost->draws) : kNaN});
    return f;
}

nlohmann::ordered_json toJson(const PointResult& r) {
    nlohmann::ordered_json figures = nlohmann::ordered_json::object();
    for (const auto& [k, v] : r.figures) figures[k] = figureJson(v);
    return {{"version", kSweepVersion}, {"id", r.id}, {"label", r.label}, {"reference", r.reference},
            {"axisValues", r.axisValues}, {"figures", figures}, {"settings", r.settings}};
}

PointResult pointFromJson(const nlohmann::ordered_json& j, const std::string& source) {
    try {
        PointResult r;
        r.id = j.at("id").get<std::string>();
        r.label = j.at("label").get<std::string>();
        r.reference = j.at("reference").get<bool>();
        r.axisValues = j.at("axisValues").get<std::vector<std::string>>();
        r.settings = j.at("settings");
        for (const auto& [k, v] : j.at("figures").items()) r.figures.push_back({k, v.is_number() ? v.get<double>() : kNaN});
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(source + ": not a sweep point result: " + e.what());
    }
}

Manifest manifestOf(const SweepSpec& spec, const std::vector<Point>& points, const std::string& machine) {
    Manifest m;
    m.sweep = spec.name;
    m.fingerprint = fingerprintOf(spec, points);
    m.scene = spec.base.scene;
    m.presetDir = std::filesystem::absolute(spec.presetDir).lexically_normal();
    m.width = spec.base.output.width;
    m.height = spec.base.output.height;
    for (const Axis& a : spec.axes) {
        m.axisFields.emplace_back(a.field->path);
        m.axisValues.push_back(a.valueText);
        const std::string base = fieldValueToJson(*a.field, a.field->get(spec.base)).dump();
        bool listed = false;
        for (const std::string& v : a.valueText) listed = listed || v == base;
        m.baseValues.push_back(listed ? base : a.valueText.front());
    }
    for (const Point& p : points) m.pointIds.push_back(p.id);
    m.machine = machine;
    return m;
}

nlohmann::ordered_json toJson(const Manifest& m) {
    nlohmann::ordered_json axes = nlohmann::ordered_json::array();
    for (std::size_t a = 0; a < m.axisFields.size(); ++a)
        axes.push_back({{"field", m.axisFields[a]}, {"values", m.axisValues[a]}, {"base", m.baseValues[a]}});
    return {{"version", kSweepVersion}, {"sweep", m.sweep}, {"fingerprint", m.fingerprint}, {"scene", m.scene},
            {"presetDir", m.presetDir.string()}, {"width", m.width}, {"height", m.height}, {"axes", axes},
            {"points", m.pointIds}, {"machine", m.machine}};
}

Manifest manifestFromJson(const nlohmann::ordered_json& j, const std::string& source) {
    try {
        Manifest m;
        m.sweep = j.at("sweep").get<std::string>();
        m.fingerprint = j.at("fingerprint").get<std::string>();
        m.scene = j.at("scene").get<std::string>();
        m.presetDir = j.at("presetDir").get<std::string>();
        m.width = j.at("width").get<int>();
        m.height = j.at("height").get<int>();
        for (const auto& a : j.at("axes")) {
            m.axisFields.push_back(a.at("field").get<std::string>());
            m.axisValues.push_back(a.at("values").get<std::vector<std::string>>());
            m.baseValues.push_back(a.at("base").get<std::string>());
        }
        m.pointIds = j.at("points").get<std::vector<std::string>>();
        m.machine = j.at("machine").get<std::string>();
        return m;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(source + ": not a sweep manifest: " + e.what());
    }
}

const std::vector<std::pair<std::string, std::string>>& softErrorKeys() {
    static const std::vector<std::pair<std::string, std::string>> keys{
        {"soft-filtered", "soft_filtered_error"},     {"acne", "acne_pct"},
        {"light-bleeding", "light_bleeding_pct"},     {"peter-panning", "peter_panning_pct"},
        {"missing-caster", "missing_caster_pct"},     {"penumbra-width", "penumbra_width_abs_error_px"}};
    return keys;
}

std::vector<std::string> errorChoices() {
    std::vector<std::string> out{"misclassified", "filtered", "flicker"};
    for (const auto& [name, key] : softErrorKeys()) out.push_back(name);
    return out;
}

std::string errorNames() {
    std::string out;
    for (const std::string& n : errorChoices()) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string errorKey(const std::string& error) {
    if (error == "misclassified") return "misclassified_pct";
    if (error == "filtered") return "filtered_error";
    if (error == "flicker") return "flicker_F_pct";
    for (const auto& [name, key] : softErrorKeys())
        if (error == name) return key;
    throw std::invalid_argument("--error must be one of " + errorNames() + ", got \"" + error + "\"");
}

}  // namespace st::sweep
