#pragma once
// Two measurements side by side (`shadowtune compare`): the headline figures of each, their
// deltas B - A, and where the two unfiltered shadow tests disagree. Pure: no GL, no files.
#include "metrics/figure_table.h"
#include "metrics/measure_session.h"
#include "renderer/render/measure_samples.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace st::metrics {

struct CompareFigure {
    std::string key;    // its path in compare.json, e.g. "accuracy.misclassified"
    std::string label;  // its name in the terminal table
    FigureUnit unit = FigureUnit::Share;
    std::optional<double> a, b;  // absent: no camera path (flicker) or no cost measured
    std::optional<double> delta() const { return a && b ? std::optional<double>(*b - *a) : std::nullopt; }
};

// The rows of `table` shown in compare (Shows::InCompare), in table order.
std::vector<CompareFigure> compareFigures(const PresetMeasurement& a, const PresetMeasurement& b,
                                          const FigureTable& table = figureTable());

// One pixel of the two unfiltered shadow tests (MeasureSamples::shadow.x) of the same view.
enum class DiffClass : std::uint8_t { Unscored, Neither, Both, OnlyA, OnlyB };

struct ShadowDiff {
    int width = 0;
    int height = 0;
    std::vector<DiffClass> classes;  // per pixel, top row first
    std::size_t unscored = 0;        // not a receiver in A or in B (no surface, facing away)
    std::size_t neither = 0, both = 0, onlyA = 0, onlyB = 0;
    std::size_t scored() const { return neither + both + onlyA + onlyB; }
    double share(std::size_t n) const { return scored() ? double(n) / double(scored()) : 0.0; }
};

// Throws std::invalid_argument when the sizes differ.
ShadowDiff shadowDiff(const MeasureSamples& a, const MeasureSamples& b);

struct CompareNames {
    std::string a, b;          // preset names (file stems)
    std::string fileA, fileB;  // as given
    bool sharedView = true;    // B measured with A's scene, camera and light (no --keep-b-scene)
};

// compare.json: {"a": {...}, "b": {...}, "delta": {...}, "shadowDiff": {...} or null, ...}; the
// figures sit at their keys' paths, null where absent.
nlohmann::ordered_json compareJson(const CompareNames& names, const std::vector<CompareFigure>& figures,
                                   const PresetMeasurement& a, const std::optional<ShadowDiff>& diff);

// The table printed on the terminal: one row per figure, A, B and B - A with units and signs.
std::string compareTable(const CompareNames& names, const std::vector<CompareFigure>& figures,
                         const std::optional<ShadowDiff>& diff);
// formatValue / formatDelta (metrics/figure_table.h) print each cell.

}  // namespace st::metrics
