#pragma once
// What a sweep keeps of each point (its settings and every figure `measure` reports), the
// manifest that ties a result folder to its sweep, and the report written from them: results.csv
// and .json, the Pareto charts, one chart per axis, front.json and front/*.json. No GL.
#include "metrics/measure_session.h"
#include "sweep/sweep_spec.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace st::sweep {

// figure key (unit in the name) -> value; NaN where it does not apply (flicker without a path).
using Figures = std::vector<std::pair<std::string, double>>;

struct PointResult {
    std::string id;
    std::string label;
    bool reference = false;
    std::vector<std::string> axisValues;
    nlohmann::ordered_json settings;  // the point as a preset (scene path as in the base preset)
    Figures figures;
    double figure(const std::string& key) const;  // NaN if absent
};

Figures figuresOf(const metrics::PresetMeasurement& m);

nlohmann::ordered_json toJson(const PointResult& r);
// Throws std::runtime_error naming `source` for a file that is not a point result.
PointResult pointFromJson(const nlohmann::ordered_json& j, const std::string& source);

// Ties a folder of point files to one sweep: shards and resumed runs must agree on it.
struct Manifest {
    std::string sweep;       // name
    std::string fingerprint; // of the sweep's points (ids and order) and axes
    std::string scene;
    std::filesystem::path presetDir;  // absolute: where the base's relative scene path starts
    int width = 0, height = 0;
    std::vector<std::string> axisFields;
    std::vector<std::vector<std::string>> axisValues;
    std::vector<std::string> baseValues;  // per axis, the value the per-axis charts hold the others at
    std::vector<std::string> pointIds;    // every point of the sweep, in order
    std::string machine;                  // renderer and cores of the machine(s) that ran it
};

Manifest manifestOf(const SweepSpec& spec, const std::vector<Point>& points, const std::string& machine);
nlohmann::ordered_json toJson(const Manifest& m);
Manifest manifestFromJson(const nlohmann::ordered_json& j, const std::string& source);

// The figure the charts and the front minimise: "misclassified", "filtered", "flicker", or one
// against the soft truth: "soft-filtered", "acne", "light-bleeding", "peter-panning",
// "missing-caster", "penumbra-width" (|filtered - true| mean width, px).
struct ReportOptions {
    std::string error = "misclassified";
};
std::string errorKey(const std::string& error);  // "misclassified_pct", ...; throws for others
std::vector<std::string> errorChoices();          // every name errorKey() takes
std::string errorNames();                          // the same, comma-separated
// The soft-truth names of errorChoices() and their figure keys.
const std::vector<std::pair<std::string, std::string>>& softErrorKeys();

// Writes every report file into `dir` from the points found (any subset of the manifest's).
// Returns the ids of the front points.
std::vector<std::string> writeReport(const std::filesystem::path& dir, const Manifest& m,
                                     const std::vector<PointResult>& results, const ReportOptions& opt);

}  // namespace st::sweep
