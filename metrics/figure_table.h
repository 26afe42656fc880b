#pragma once
// The one table of figures (issue 18; the settings' counterpart is renderer/settings/field_table.h):
// a row per figure the product reports, with its key, label, unit, which way is better, how to
// read it from a measurement and where it appears. metrics.json, compare.json and compare's
// table, the sweep's results.csv/.json, --error and cost choices and chart axes, the editor's
// Accuracy and Sweep panels and docs/metrics.md are generated from it: adding a figure is adding
// a row in figure_table.cpp (and regenerating docs/metrics.md).
#include "metrics/measure_session.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace st::metrics {

// How a figure is shown. Machine-readable outputs (metrics.json, compare.json, results.csv/.json)
// always hold the raw value (a share as a fraction, bytes as bytes); text, charts and panels show
// it scaled (a share as %, bytes as MiB).
enum class FigureUnit { Share, Error, PxPerTexel, Px, Ms, Bytes, Count };

enum class Better { Lower, Higher, None };

// Where a figure appears (FigureRow::shows, OR-ed).
enum Shows : unsigned {
    InMetricsJson = 1u << 0,     // metrics.json at the key's path
    InCompare = 1u << 1,         // compare.json and compare's terminal table
    InSweep = 1u << 2,           // results.csv / results.json columns, the Sweep panel's hover
    ErrorChoice = 1u << 3,       // a sweep --error choice (chart y axis, the front's error)
    CostChoice = 1u << 4,        // a sweep cost choice (chart x axis, the front's cost)
    InEditorAccuracy = 1u << 5,  // the editor's Accuracy panel: may read only m.accuracy.all, m.soft.all, m.soft.penumbra
    InEditorSweep = 1u << 6,     // the editor's Sweep panel: a point's hover text
};

using FigureRead = std::function<std::optional<double>(const PresetMeasurement&)>;

struct FigureRow {
    std::string key;          // one name everywhere: its dotted path in metrics.json, "accuracy.misclassified"
    std::string label;        // tables and panels: "misclassified"
    FigureUnit unit = FigureUnit::Share;
    Better better = Better::Lower;
    FigureRead read;          // absent where it does not apply (no camera path, no cost measured)
    std::string choice;       // sweep --error / cost choice name, "" if neither
    std::string axisTitle;    // chart axis: "misclassified (% of sun-facing pixels)"
    std::string description;  // one line, for docs and hover texts
    unsigned shows = 0;       // Shows flags
    bool timing = false;      // a measured time: differs between runs (every other figure is repeatable)
    bool has(Shows s) const { return (shows & s) != 0; }
};

using FigureTable = std::vector<FigureRow>;

// Every figure, in the order the outputs list them (the CSV's column order).
const FigureTable& figureTable();

// The row of `key`, or nullptr.
const FigureRow* findFigure(const std::string& key, const FigureTable& table = figureTable());
// The rows with flag `s`, in table order.
std::vector<const FigureRow*> figuresShown(Shows s, const FigureTable& table = figureTable());
// The choice names of the rows with `s` (ErrorChoice or CostChoice), in table order.
std::vector<std::string> choicesOf(Shows s, const FigureTable& table = figureTable());
// The row whose choice is `name` among those with `s`. Throws std::invalid_argument naming the
// choices ("--error must be one of misclassified, filtered, ...").
const FigureRow& figureByChoice(const std::string& name, Shows s, const FigureTable& table = figureTable());

// Units: the symbol shown after a value ("%", "MiB", "" for none), the factor from the raw value
// to the shown one, and the symbol of a difference ("pp" for a share).
struct UnitInfo {
    const char* name;         // docs: "share", "bytes", ...
    const char* symbol;       // "%"
    const char* deltaSymbol;  // "pp"
    double scale;             // shown = raw * scale
    int decimals;
    const char* raw;          // docs: what the raw value is ("fraction 0..1")
    const char* shownAs;      // docs: "% (x 100)"
};
const UnitInfo& unitInfo(FigureUnit unit);
double shown(FigureUnit unit, double raw);  // raw * scale
// "1.234 %", "0.0123", "1.25 ms", "16.0 MiB", ...; "-" if absent.
std::string formatValue(FigureUnit unit, std::optional<double> value);
// The same for a difference, always signed ("+0.512 pp", "-3.00 ms"); exactly zero is "±0".
std::string formatDelta(FigureUnit unit, std::optional<double> delta);
// "%", "MiB": the unit as a title shows it ("" for none).
std::string unitSuffix(FigureUnit unit);

// A raw value as JSON: counts and bytes as integers, null if absent.
nlohmann::ordered_json figureJson(FigureUnit unit, std::optional<double> value);
// "/accuracy/misclassified" for "accuracy.misclassified".
std::string jsonPointer(const std::string& key);

// One figure of a measurement, ready to show.
struct FigureValue {
    const FigureRow* row = nullptr;
    std::optional<double> value;
};
std::vector<FigureValue> readFigures(const PresetMeasurement& m, Shows s, const FigureTable& table = figureTable());

// docs/metrics.md: every row, grouped by its key's first part (scripts/ and the docs test).
std::string figuresMarkdown(const FigureTable& table = figureTable());

}  // namespace st::metrics
