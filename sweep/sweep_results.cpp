#include "sweep/sweep_results.h"

#include "renderer/settings/settings_json.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace st::sweep {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string fingerprintOf(const SweepSpec& spec, const std::vector<Point>& points) {
    std::string text;
    for (const Axis& a : spec.axes) text += std::string(a.field->path) + ";";
    for (const Point& p : points) text += p.id + ",";
    return fnv1aHex(text);
}

// JSON has no NaN: a figure that does not apply is written as null.
nlohmann::ordered_json figureJson(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); }

// A folder of another version has other figure keys: mixing its points with new ones would give
// a report of half-empty columns, so it is refused, saying what to do.
void checkVersion(const nlohmann::ordered_json& j, const std::string& source) {
    const int version = j.is_object() && j.contains("version") && j["version"].is_number_integer() ? j["version"].get<int>() : 0;
    if (version == kSweepResultsVersion) return;
    throw std::runtime_error(source + ": written with sweep results version " + std::to_string(version) +
                             (version < kSweepResultsVersion ? " (figure keys before the figure table, e.g. misclassified_pct)" : "") +
                             "; this shadowtune reads version " + std::to_string(kSweepResultsVersion) +
                             ": measure into another --out folder, or remove this one");
}
}  // namespace

double PointResult::figure(const std::string& key) const {
    for (const auto& [k, v] : figures)
        if (k == key) return v;
    return kNaN;
}

Figures figuresOf(const metrics::PresetMeasurement& m, const metrics::FigureTable& table) {
    Figures f;
    for (const metrics::FigureValue& v : metrics::readFigures(m, metrics::InSweep, table))
        f.push_back({v.row->key, v.value.value_or(kNaN)});
    return f;
}

nlohmann::ordered_json toJson(const PointResult& r) {
    nlohmann::ordered_json figures = nlohmann::ordered_json::object();
    for (const auto& [k, v] : r.figures) figures[k] = figureJson(v);
    return {{"version", kSweepResultsVersion}, {"id", r.id}, {"label", r.label}, {"reference", r.reference},
            {"axisValues", r.axisValues}, {"figures", figures}, {"settings", r.settings}};
}

PointResult pointFromJson(const nlohmann::ordered_json& j, const std::string& source) {
    checkVersion(j, source);
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

Manifest manifestOf(const SweepSpec& spec, const std::vector<Point>& points, const std::string& machine,
                    const std::string& costProfile) {
    Manifest m;
    m.sweep = spec.name;
    m.fingerprint = fingerprintOf(spec, points);
    m.scene = spec.base.scene;
    m.presetDir = std::filesystem::absolute(spec.presetDir).lexically_normal();
    if (!m.presetDir.has_filename()) m.presetDir = m.presetDir.parent_path();  // "/x/." normalises to "/x/"
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
    m.costProfile = costProfile;
    return m;
}

nlohmann::ordered_json toJson(const Manifest& m) {
    nlohmann::ordered_json axes = nlohmann::ordered_json::array();
    for (std::size_t a = 0; a < m.axisFields.size(); ++a)
        axes.push_back({{"field", m.axisFields[a]}, {"values", m.axisValues[a]}, {"base", m.baseValues[a]}});
    return {{"version", kSweepResultsVersion}, {"sweep", m.sweep}, {"fingerprint", m.fingerprint}, {"scene", m.scene},
            {"presetDir", m.presetDir.string()}, {"width", m.width}, {"height", m.height}, {"axes", axes},
            {"points", m.pointIds}, {"machine", m.machine}, {"costProfile", m.costProfile}};
}

Manifest manifestFromJson(const nlohmann::ordered_json& j, const std::string& source) {
    checkVersion(j, source);
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
        m.costProfile = j.value("costProfile", "");
        return m;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(source + ": not a sweep manifest: " + e.what());
    }
}

const metrics::FigureRow& errorFigure(const std::string& error, const metrics::FigureTable& table) {
    return metrics::figureByChoice(error, metrics::ErrorChoice, table);
}

const metrics::FigureRow& costFigure(const std::string& cost, const metrics::FigureTable& table) {
    return metrics::figureByChoice(cost, metrics::CostChoice, table);
}

std::vector<std::string> errorChoices() { return metrics::choicesOf(metrics::ErrorChoice); }
std::vector<std::string> costChoices() { return metrics::choicesOf(metrics::CostChoice); }

std::string errorNames() {
    std::string out;
    for (const std::string& n : errorChoices()) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string errorKey(const std::string& error) { return errorFigure(error).key; }

std::string shortName(const metrics::FigureRow& row) {
    const std::string unit = metrics::unitSuffix(row.unit);
    return unit.empty() ? row.label : row.label + " " + unit;
}

}  // namespace st::sweep
