#pragma once
// Two measurements side by side (`shadowtune compare`): the headline figures of each, their
// deltas B - A, and where the two unfiltered shadow tests disagree. Pure: no GL, no files.
#include "metrics/measure_session.h"
#include "renderer/render/measure_samples.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace st::metrics {

// How a figure is printed: shares as % (deltas in percentage points), times in ms, memory in
// MiB; JSON always holds the raw value (a share as a fraction, bytes as bytes).
enum class FigureUnit { Share, Error, PxPerTexel, Ms, Bytes, Count };

struct CompareFigure {
    std::string key;    // its path in compare.json, e.g. "accuracy.misclassified"
    std::string label;  // its name in the terminal table
    FigureUnit unit = FigureUnit::Share;
    std::optional<double> a, b;  // absent: no camera path (flicker) or no cost measured
    std::optional<double> delta() const { return a && b ? std::optional<double>(*b - *a) : std::nullopt; }
};

// Accuracy (misclassified, false shadow, false light, edge band, gross, filtered error),
// texel density (median, p90, p95), flicker F, cost (GPU shadow and main ms, shadow-map bytes,
// caster triangles), in that order.
std::vector<CompareFigure> compareFigures(const PresetMeasurement& a, const PresetMeasurement& b);

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

// "1.234 %", "0.0123", "1.25 ms", "16.0 MiB", ...: a value as the table prints it; "-" if absent.
std::string formatValue(FigureUnit unit, std::optional<double> value);
// The same for a delta, always signed ("+0.512 pp", "-3.00 ms"); exactly zero is "±0".
std::string formatDelta(FigureUnit unit, std::optional<double> delta);

}  // namespace st::metrics
