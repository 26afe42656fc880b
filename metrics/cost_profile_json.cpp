#include "metrics/cost_profile_json.h"

#include "renderer/image/image_io.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace st::metrics {
namespace {

using Json = nlohmann::ordered_json;

// Reads one profile, throwing at the first problem with its path.
struct Reader {
    const std::string& file;

    [[noreturn]] void fail(const std::string& path, const std::string& reason) const {
        throw CostProfileError(file, path, reason);
    }
    const Json& member(const Json& obj, const std::string& path, const std::string& key) const {
        if (!obj.contains(key)) fail(path.empty() ? key : path + "." + key, "missing");
        return obj[key];
    }
    std::string text(const Json& obj, const std::string& path, const std::string& key) const {
        const Json& v = member(obj, path, key);
        if (!v.is_string()) fail(path + "." + key, std::string("expected a string, got ") + v.type_name());
        return v.get<std::string>();
    }
    double number(const Json& v, const std::string& path) const {
        if (!v.is_number()) fail(path, std::string("expected a number, got ") + v.type_name());
        const double d = v.get<double>();
        if (!std::isfinite(d)) fail(path, "expected a finite number");
        return d;
    }
    double number(const Json& obj, const std::string& path, const std::string& key) const {
        return number(member(obj, path, key), path + "." + key);
    }
    int count(const Json& obj, const std::string& path, const std::string& key) const {
        const Json& v = member(obj, path, key);
        if (!v.is_number_integer() || v.get<long long>() < 0)
            fail(path + "." + key, "expected a non-negative integer");
        return v.get<int>();
    }
    void object(const Json& v, const std::string& path) const {
        if (!v.is_object()) fail(path, std::string("expected an object, got ") + v.type_name());
    }

    PassModel pass(const Json& v, const std::string& path) const {
        object(v, path);
        PassModel m;
        const Json& coefficients = member(v, path, "coefficients");
        object(coefficients, path + ".coefficients");
        for (const auto& [name, value] : coefficients.items()) {
            const std::string at = path + ".coefficients." + name;
            const std::optional<Feature> f = featureFromName(name);
            if (!f) fail(at, "unknown feature (expected intercept or a PassWork counter: draws, vertices, ...)");
            const double ms = number(value, at);
            if (ms < 0) fail(at, "a coefficient is milliseconds per unit and cannot be negative");
            m.terms.push_back({*f, ms});
        }
        m.r2 = number(v, path, "r2");
        m.samples = count(v, path, "samples");
        if (v.contains("calibrated")) m.calibrated = text(v, path, "calibrated");
        return m;
    }

    Residual residual(const Json& v, const std::string& path) const {
        object(v, path);
        return {text(v, path, "preset"), text(v, path, "pass"), number(v, path, "minMs"), number(v, path, "medianMs"),
                number(v, path, "modelMs")};
    }

    CostProfile profile(const Json& root) const {
        if (!root.is_object()) fail("(top level)", std::string("expected an object, got ") + root.type_name());
        const Json& version = member(root, "", "version");
        if (version != kCostProfileVersion) fail("version", "must be " + std::to_string(kCostProfileVersion));
        CostProfile p;
        p.renderer = text(root, "", "renderer");
        p.machine = text(root, "", "machine");
        p.date = text(root, "", "date");
        p.frames = count(root, "", "frames");
        p.fittedOn = text(root, "", "fittedOn");
        p.frameR2 = number(root, "", "frameR2");
        const Json& passes = member(root, "", "passes");
        object(passes, "passes");
        for (const auto& [name, value] : passes.items()) {
            const std::optional<PassKind> k = passKindFromName(name);
            if (!k) fail("passes." + name, "unknown pass (expected cascade, main, filter or depthBounds)");
            p.pass(*k) = pass(value, "passes." + name);
        }
        const Json& residuals = member(root, "", "residuals");
        if (!residuals.is_array()) fail("residuals", std::string("expected an array, got ") + residuals.type_name());
        for (std::size_t i = 0; i < residuals.size(); ++i)
            p.residuals.push_back(residual(residuals[i], "residuals[" + std::to_string(i) + "]"));
        return p;
    }
};

}  // namespace

CostProfileError::CostProfileError(const std::string& file, const std::string& jsonPath, const std::string& reason)
    : std::runtime_error(file + ": " + jsonPath + ": " + reason), path_(jsonPath) {}

Json toJson(const CostProfile& p) {
    Json root;
    root["version"] = kCostProfileVersion;
    root["renderer"] = p.renderer;
    root["machine"] = p.machine;
    root["date"] = p.date;
    root["frames"] = p.frames;
    root["fittedOn"] = p.fittedOn;
    root["frameR2"] = p.frameR2;
    Json passes = Json::object();
    for (PassKind k : kPassKinds) {
        const PassModel& m = p.pass(k);
        Json coefficients = Json::object();
        for (const Term& t : m.terms) coefficients[featureName(t.feature)] = t.msPerUnit;
        Json pass{{"coefficients", coefficients}, {"r2", m.r2}, {"samples", m.samples}};
        if (!m.calibrated.empty()) pass["calibrated"] = m.calibrated;
        passes[passKindName(k)] = std::move(pass);
    }
    root["passes"] = passes;
    Json residuals = Json::array();
    for (const Residual& r : p.residuals)
        residuals.push_back(Json{{"preset", r.preset}, {"pass", r.pass}, {"minMs", r.minMs},
                                 {"medianMs", r.medianMs}, {"modelMs", r.modelMs}});
    root["residuals"] = residuals;
    return root;
}

CostProfile costProfileFromJson(const Json& root, const std::string& file) { return Reader{file}.profile(root); }

CostProfile loadCostProfile(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw CostProfileError(file.string(), "(top level)", "cannot open the file");
    std::stringstream text;
    text << in.rdbuf();
    Json root;
    try {
        root = Json::parse(text.str());
    } catch (const nlohmann::json::parse_error& e) {
        throw CostProfileError(file.string(), "(top level)", std::string("not valid JSON: ") + e.what());
    }
    return costProfileFromJson(root, file.string());
}

void saveCostProfileAtomic(const CostProfile& p, const std::filesystem::path& file) {
    writeTextAtomic(file, toJson(p).dump(2) + "\n");
}

}  // namespace st::metrics
