#pragma once
// What a sweep keeps of each point (its settings and every figure `measure` reports), the
// manifest that ties a result folder to its sweep, and the report written from them: results.csv
// and .json, the Pareto charts, one chart per axis, front.json and front/*.json. No GL.
#include "metrics/figure_table.h"
#include "metrics/measure_session.h"
#include "sweep/sweep_spec.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace st::sweep {

// The version of a sweep folder's sweep.json and points/*.json (not of sweep files: kSweepVersion).
// 2: figures keyed by the figure table's keys ("accuracy.misclassified") with raw values (shares
// as fractions, bytes as bytes); 1 had "misclassified_pct" and the like, in display units.
inline constexpr int kSweepResultsVersion = 2;

// figure key (metrics/figure_table.h) -> raw value; NaN where it does not apply (flicker without a path).
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

// The figures of the table's rows shown in sweeps, in table order.
Figures figuresOf(const metrics::PresetMeasurement& m, const metrics::FigureTable& table = metrics::figureTable());

nlohmann::ordered_json toJson(const PointResult& r);
// Throws std::runtime_error naming `source` for a file that is not a point result.
// Throws too for a result of another kSweepResultsVersion, saying so.
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
    std::string costProfile;              // the cost model's profile (metrics::profileName), "" without one
};

Manifest manifestOf(const SweepSpec& spec, const std::vector<Point>& points, const std::string& machine,
                    const std::string& costProfile = "");
nlohmann::ordered_json toJson(const Manifest& m);
// Throws std::runtime_error naming `source` for a file that is not a manifest, or one of a folder
// written by a version of shadowtune with other figure keys.
Manifest manifestFromJson(const nlohmann::ordered_json& j, const std::string& source);

// The figures the charts and the front trade: an error (the table's ErrorChoice rows:
// "misclassified", "filtered", "flicker", "soft-filtered", "acne", ...) against a cost (its
// CostChoice rows: "model", the cost model's figure, which does not move with the machine's load;
// "measured" GPU time; the memory chart uses "memory").
struct ReportOptions {
    std::string error = "misclassified";
    std::string cost = "model";
};
// The row of a choice; throws std::invalid_argument listing the choices for others.
const metrics::FigureRow& errorFigure(const std::string& error, const metrics::FigureTable& table = metrics::figureTable());
const metrics::FigureRow& costFigure(const std::string& cost, const metrics::FigureTable& table = metrics::figureTable());
inline constexpr const char* kMemoryChoice = "memory";  // the x axis of pareto-memory.png
std::string errorKey(const std::string& error);   // "accuracy.misclassified", ...; throws for others
std::vector<std::string> errorChoices();          // every name errorKey() takes
std::string errorNames();                          // the same, comma-separated
std::vector<std::string> costChoices();            // every name costFigure() takes

// A figure's title word with its unit: "misclassified %", "GPU total ms".
std::string shortName(const metrics::FigureRow& row);

// `settings` (a preset whose relative scene path starts at `presetDir`) as a preset saved in
// `folder`: the scene path rewritten relative to it, or absolute where no relative path exists.
nlohmann::ordered_json presetInFolder(const std::filesystem::path& folder, const std::filesystem::path& presetDir,
                                      nlohmann::ordered_json settings);

// Writes every report file into `dir` from the points found (any subset of the manifest's).
// Returns the ids of the front points.
// results.csv has the table's sweep rows as columns, in table order.
std::vector<std::string> writeReport(const std::filesystem::path& dir, const Manifest& m,
                                     const std::vector<PointResult>& results, const ReportOptions& opt,
                                     const metrics::FigureTable& table = metrics::figureTable());

}  // namespace st::sweep
