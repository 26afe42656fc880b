#include "metrics/figure_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace st::metrics {
namespace {
using Figure = std::optional<double>;
using M = PresetMeasurement;

constexpr unsigned kEverywhere = InMetricsJson | InCompare | InSweep;

Figure share(const ErrorCounts& e, std::size_t n) { return e.share(n); }
Figure softShare(const ArtifactCounts& k, std::size_t n) { return k.share(n); }
template <class T>
Figure costOf(const M& m, T CostReport::*field) {
    return m.cost ? Figure(double((*m.cost).*field)) : std::nullopt;
}

Figure modelOf(const M& m, double ModelledCost::*field) {
    return m.cost && m.cost->model ? Figure((*m.cost->model).*field) : std::nullopt;
}

// The rows, in output order. A cost row is one row: its read picks the field of CostReport (or
// of whatever report the figure comes from) and its flags say where it goes.
FigureTable makeTable() {
    const auto all = [](const M& m) -> const ErrorCounts& { return m.accuracy.all; };
    const auto soft = [](const M& m) -> const ArtifactCounts& { return m.soft.all; };
    const char* ofReceivers = "% of sun-facing pixels";
    FigureTable t = {
        {"accuracy.misclassified", "misclassified", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return share(all(m), all(m).misclassified()); }, "misclassified",
         std::string("misclassified (") + ofReceivers + ")",
         "Share of sun-facing pixels whose unfiltered shadow test disagrees with the ray-cast truth "
         "(false shadow + false light).",
         kEverywhere | ErrorChoice | InEditorAccuracy | InEditorSweep},
        {"accuracy.falseShadow", "false shadow", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return share(all(m), all(m).falseShadow()); }, "",
         std::string("false shadow (") + ofReceivers + ")",
         "Share of sun-facing pixels the map shadows where the truth is lit (acne-like).",
         kEverywhere | InEditorAccuracy | InEditorSweep},
        {"accuracy.falseLight", "false light", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return share(all(m), all(m).falseLight()); }, "",
         std::string("false light (") + ofReceivers + ")",
         "Share of sun-facing pixels the map lights where the truth is shadowed (leaks, peter-panning).",
         kEverywhere | InEditorAccuracy | InEditorSweep},
        {"accuracy.edgeBand", "edge band errors", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return share(all(m), all(m).falseShadowEdge + all(m).falseLightEdge); }, "",
         std::string("edge band errors (") + ofReceivers + ")",
         "Misclassified pixels within a texel footprint of a true shadow edge: what the map's resolution explains.",
         kEverywhere | InEditorAccuracy},
        {"accuracy.grossShare", "gross errors", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return share(all(m), all(m).gross()); }, "", std::string("gross errors (") + ofReceivers + ")",
         "Misclassified pixels away from any true edge: real artifacts (acne, leaks, missing casters).",
         kEverywhere | InEditorAccuracy | InEditorSweep},
        {"accuracy.grossPixels", "gross error pixels", FigureUnit::Count, Better::Lower,
         [=](const M& m) -> Figure { return double(all(m).gross()); }, "", "gross errors (pixels)",
         "Count of gross errors: few when settings are sane, and each one is visible.",
         InMetricsJson | InSweep | InEditorAccuracy},
        {"accuracy.filteredError", "filtered error", FigureUnit::Error, Better::Lower,
         [=](const M& m) -> Figure { return all(m).filteredError(); }, "filtered",
         "filtered error (mean |filtered - truth|)",
         "Mean |filtered shadow factor - point truth| over sun-facing pixels (0 exact, 1 every pixel inverted).",
         kEverywhere | ErrorChoice | InEditorAccuracy | InEditorSweep},
        {"accuracy.receivers", "sun-facing pixels", FigureUnit::Count, Better::None,
         [=](const M& m) -> Figure { return double(all(m).receivers); }, "", "sun-facing pixels",
         "Pixels facing the sun: the denominator of every accuracy share.", InMetricsJson | InSweep | InEditorAccuracy},

        {"texelDensity.median", "px/texel median", FigureUnit::PxPerTexel, Better::None,
         [](const M& m) -> Figure { return m.density.all.median; }, "", "texel density, median (px/texel)",
         "Median screen pixels per shadow-map texel over surface pixels in the shadow range (about 1 is matched).",
         kEverywhere | InEditorSweep},
        {"texelDensity.p90", "px/texel p90", FigureUnit::PxPerTexel, Better::Lower,
         [](const M& m) -> Figure { return m.density.all.p90; }, "", "texel density, 90th percentile (px/texel)",
         "90th percentile of pixels per texel: how blocky the worst tenth of the view is.", kEverywhere},
        {"texelDensity.p95", "px/texel p95", FigureUnit::PxPerTexel, Better::Lower,
         [](const M& m) -> Figure { return m.density.all.p95; }, "", "texel density, 95th percentile (px/texel)",
         "95th percentile of pixels per texel.", kEverywhere},
        {"texelDensity.aliasingShare", "aliased", FigureUnit::Share, Better::Lower,
         [](const M& m) -> Figure { return m.density.all.aliasingShare; }, "", "aliased (% of pixels in range)",
         "Share of pixels in the shadow range with more than one pixel per texel (visible blocks).",
         kEverywhere | InEditorSweep},

        {"flicker.flipRate", "flicker F", FigureUnit::Share, Better::Lower,
         [](const M& m) { return m.flicker ? Figure(m.flicker->flipRate) : std::nullopt; }, "flicker",
         "flicker F (% of sun-facing pixels per frame)",
         "Mean share of sample points whose hard shadow result flips between consecutive frames of the camera "
         "path; absent without a path.",
         kEverywhere | ErrorChoice},
        {"flicker.alternatingPixels", "alternating pixels", FigureUnit::Count, Better::Lower,
         [](const M& m) { return m.flicker ? Figure(double(m.flicker->alternatingPixels)) : std::nullopt; }, "",
         "alternating pixels (saccade's flicker count)",
         "Sun-facing pixels whose luminance (intensity x N.L x filtered factor) changes by >= 0.02 up then down, or "
         "down then up, over 3 consecutive frames of the path (the saccade tool's flicker unit); absent without a path.",
         kEverywhere},

        {"soft.filteredError", "filtered error vs the sun's disc", FigureUnit::Error, Better::Lower,
         [=](const M& m) -> Figure { return soft(m).filteredError(); }, "soft-filtered",
         "filtered error against the sun's disc (mean |filtered - soft truth|)",
         "Mean |filtered shadow factor - visible fraction of the sun's disc| over sun-facing pixels.",
         kEverywhere | ErrorChoice | InEditorAccuracy | InEditorSweep},
        {"soft.acne", "acne", FigureUnit::Share, Better::Lower, [=](const M& m) { return softShare(soft(m), soft(m).acne); },
         "acne", "acne (% of sun-facing pixels, against the sun's disc)",
         "Share of sun-facing pixels drawn too dark where the soft truth is lit.",
         kEverywhere | ErrorChoice | InEditorAccuracy},
        {"soft.lightBleeding", "light bleeding", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return softShare(soft(m), soft(m).lightBleeding); }, "light-bleeding",
         "light bleeding (% of sun-facing pixels, against the sun's disc)",
         "Share drawn too light inside a true umbra, more than measure.artifactTexels texels from its edge.",
         kEverywhere | ErrorChoice | InEditorAccuracy},
        {"soft.peterPanning", "peter-panning", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return softShare(soft(m), soft(m).peterPanning); }, "peter-panning",
         "peter-panning (% of sun-facing pixels, against the sun's disc)",
         "Share drawn too light within measure.artifactTexels texels of a contact (a detached shadow).",
         kEverywhere | ErrorChoice | InEditorAccuracy},
        {"soft.missingCaster", "missing caster", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return softShare(soft(m), soft(m).missingCaster); }, "missing-caster",
         "missing caster (% of sun-facing pixels, against the sun's disc)",
         "Share inside a whole shadow drawn too light: a caster missing from the map.",
         kEverywhere | ErrorChoice | InEditorAccuracy},
        {"soft.edge", "soft edge errors", FigureUnit::Share, Better::Lower,
         [=](const M& m) { return softShare(soft(m), soft(m).edge); }, "",
         "edge errors (% of sun-facing pixels, against the sun's disc)",
         "Any other filtered error near a true edge or in the penumbra: the map's resolution and the filter.",
         kEverywhere | InEditorAccuracy},
        {"soft.penumbraWidth.errorPx", "penumbra width error", FigureUnit::Px, Better::None,
         [](const M& m) -> Figure { return m.soft.penumbra.errorPx(); }, "", "penumbra width error (filtered - true, px)",
         "Mean filtered penumbra width minus the true one, in pixels: negative is too sharp, positive too soft.",
         kEverywhere | InEditorAccuracy},
        {"soft.penumbraWidth.absErrorPx", "penumbra width |error|", FigureUnit::Px, Better::Lower,
         [](const M& m) -> Figure { return std::abs(m.soft.penumbra.errorPx()); }, "penumbra-width",
         "penumbra width error (|filtered - true| mean width, px)",
         "|mean filtered penumbra width - true width|, in pixels.", kEverywhere | ErrorChoice},

        {"cost.gpuShadowMs", "GPU shadow pass", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::gpuShadowMs); }, "", "GPU shadow pass (ms, median)",
         "GPU time of the shadow-map pass (timer query, median of the timed frames).", kEverywhere | InEditorSweep, true},
        {"cost.gpuFilterMs", "GPU filter passes", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::gpuFilterMs); }, "", "GPU filter passes (ms, median)",
         "GPU time of the filter's extra passes (moment maps and their blur, the screen-space path).", kEverywhere, true},
        {"cost.gpuMainMs", "GPU main pass", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::gpuMainMs); }, "", "GPU main pass (ms, median)",
         "GPU time of the main (shading) pass.", kEverywhere | InEditorSweep, true},
        {"cost.gpuMs", "GPU total", FigureUnit::Ms, Better::Lower,
         [](const M& m) {
             return m.cost ? Figure(m.cost->gpuShadowMs + m.cost->gpuFilterMs + m.cost->gpuMainMs) : std::nullopt;
         },
         "measured", "GPU time, shadow + filter + main (ms, median)",
         "Measured GPU time of the frame: shadow + filter + main pass medians.",
         kEverywhere | CostChoice | InEditorSweep, true},
        {"cost.modelMs", "modelled cost", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return modelOf(m, &ModelledCost::totalMs); }, "model",
         "modelled GPU cost, all passes (ms, cost model)",
         "The cost model's milliseconds for the frame's counted work, all passes (docs/cost-model.md): the same in "
         "every run of the same settings, whatever the machine's load.",
         kEverywhere | CostChoice | InEditorSweep},
        {"cost.model.shadowMs", "modelled shadow pass", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return modelOf(m, &ModelledCost::shadowMs); }, "", "modelled shadow pass (ms)",
         "The cost model's milliseconds for the shadow pass (every cascade redrawn).", kEverywhere},
        {"cost.model.filterMs", "modelled filter passes", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return modelOf(m, &ModelledCost::filterMs); }, "", "modelled filter passes (ms)",
         "The cost model's milliseconds for the filter's extra passes.", kEverywhere},
        {"cost.model.mainMs", "modelled main pass", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return modelOf(m, &ModelledCost::mainMs); }, "", "modelled main pass (ms)",
         "The cost model's milliseconds for the main (shading) pass.", kEverywhere},
        {"cost.model.depthBoundsMs", "modelled depth bounds", FigureUnit::Ms, Better::Lower,
         [](const M& m) { return modelOf(m, &ModelledCost::depthBoundsMs); }, "", "modelled depth prepass and reduction (ms)",
         "The cost model's milliseconds for the depth prepass and reduction (0 without depth bounds).", kEverywhere},
        {"cost.cpuMs", "CPU frame", FigureUnit::Ms, Better::Lower, [](const M& m) { return costOf(m, &CostReport::cpuMs); },
         "", "CPU time per frame (ms, median)", "CPU wall time of a frame's render call (median).",
         kEverywhere | InEditorSweep, true},
        {"cost.shadowMapBytes", "shadow-map memory", FigureUnit::Bytes, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::shadowMapBytes); }, "", "shadow-map memory (MiB)",
         "Bytes of the shadow-map array (every cascade's layer).", kEverywhere},
        {"cost.filterMapBytes", "filter-map memory", FigureUnit::Bytes, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::filterMapBytes); }, "", "filter-map memory (MiB)",
         "Bytes of the filter's own maps (moments, blur targets).", kEverywhere},
        {"cost.mapBytes", "map memory", FigureUnit::Bytes, Better::Lower,
         [](const M& m) {
             return m.cost ? Figure(double(m.cost->shadowMapBytes + m.cost->filterMapBytes)) : std::nullopt;
         },
         "memory", "shadow + filter map memory (MiB)", "Bytes of the shadow maps and the filter's maps together.",
         kEverywhere | CostChoice | InEditorSweep},
        {"cost.casterTriangles", "caster triangles", FigureUnit::Count, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::triangles); }, "", "caster triangles",
         "Triangles submitted to the shadow pass, over all cascades.", kEverywhere | InEditorSweep},
        {"cost.draws", "caster draws", FigureUnit::Count, Better::Lower,
         [](const M& m) { return costOf(m, &CostReport::draws); }, "", "caster draw calls",
         "Draw calls of the shadow pass, over all cascades.", kEverywhere},
        {"cost.sceneTriangles", "scene triangles", FigureUnit::Count, Better::None,
         [](const M& m) { return costOf(m, &CostReport::sceneTriangles); }, "", "scene triangles",
         "Triangles of the scene (what one main pass draws).", InMetricsJson | InSweep},
    };
    return t;
}

std::string printf1(const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

// The heading of a group of rows in docs/metrics.md, by the key's first part.
std::string sectionTitle(const std::string& group) {
    if (group == "accuracy") return "Accuracy against the point truth (`accuracy.*`)";
    if (group == "texelDensity") return "Texel density (`texelDensity.*`)";
    if (group == "flicker") return "Flicker along the camera path (`flicker.*`)";
    if (group == "soft") return "Filtered, against the sun's disc (`soft.*`)";
    if (group == "cost") return "Cost (`cost.*`)";
    return "`" + group + ".*`";
}

std::string whereShown(const FigureRow& r) {
    std::string out;
    const auto add = [&](Shows s, const char* name) {
        if (r.has(s)) out += (out.empty() ? "" : ", ") + std::string(name);
    };
    add(InMetricsJson, "metrics.json");
    add(InCompare, "compare");
    add(InSweep, "sweep results");
    add(ErrorChoice, "--error");
    add(CostChoice, "--cost");
    add(InEditorAccuracy, "Accuracy panel");
    add(InEditorSweep, "Sweep panel");
    return out;
}

// A Markdown table cell: "|" would end it ("mean |filtered - truth|").
std::string cell(const std::string& text) {
    std::string out;
    for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

const char* betterName(Better b) { return b == Better::Lower ? "lower" : b == Better::Higher ? "higher" : "-"; }

}  // namespace

const FigureTable& figureTable() {
    static const FigureTable table = makeTable();
    return table;
}

const FigureRow* findFigure(const std::string& key, const FigureTable& table) {
    for (const FigureRow& r : table)
        if (r.key == key) return &r;
    return nullptr;
}

std::vector<const FigureRow*> figuresShown(Shows s, const FigureTable& table) {
    std::vector<const FigureRow*> out;
    for (const FigureRow& r : table)
        if (r.has(s)) out.push_back(&r);
    return out;
}

std::vector<std::string> choicesOf(Shows s, const FigureTable& table) {
    std::vector<std::string> out;
    for (const FigureRow* r : figuresShown(s, table))
        if (!r->choice.empty()) out.push_back(r->choice);
    return out;
}

const FigureRow& figureByChoice(const std::string& name, Shows s, const FigureTable& table) {
    for (const FigureRow* r : figuresShown(s, table))
        if (r->choice == name) return *r;
    std::string names;
    for (const std::string& c : choicesOf(s, table)) names += (names.empty() ? "" : ", ") + c;
    throw std::invalid_argument(std::string(s == CostChoice ? "--cost" : "--error") + " must be one of " + names +
                                ", got \"" + name + "\"");
}

const UnitInfo& unitInfo(FigureUnit unit) {
    static const UnitInfo units[] = {
        {"share", "%", "pp", 100.0, 3, "fraction 0..1", "% (x 100, 3 decimals; differences in pp)"},
        {"error", "", "", 1.0, 4, "mean absolute difference of shadow factors, 0..1", "number, 4 decimals"},
        {"px/texel", "", "", 1.0, 2, "screen pixels per shadow-map texel", "number, 2 decimals"},
        {"pixels", "px", "px", 1.0, 2, "screen pixels", "px, 2 decimals"},
        {"milliseconds", "ms", "ms", 1.0, 2, "milliseconds", "ms, 2 decimals"},
        {"bytes", "MiB", "MiB", 1.0 / (1024.0 * 1024.0), 1, "bytes (integer)", "MiB (/ 2^20, 1 decimal)"},
        {"count", "", "", 1.0, 0, "count (integer)", "whole number"},
    };
    return units[int(unit)];
}

double shown(FigureUnit unit, double raw) { return raw * unitInfo(unit).scale; }

std::string unitSuffix(FigureUnit unit) { return unitInfo(unit).symbol; }

std::string formatValue(FigureUnit unit, std::optional<double> v) {
    if (!v) return "-";
    const UnitInfo& u = unitInfo(unit);
    char format[16];
    std::snprintf(format, sizeof format, "%%.%df%s%s", u.decimals, *u.symbol ? " " : "", u.symbol);
    return printf1(format, shown(unit, *v));
}

std::string formatDelta(FigureUnit unit, std::optional<double> d) {
    if (!d) return "-";
    const UnitInfo& u = unitInfo(unit);
    const std::string suffix = *u.deltaSymbol ? std::string(" ") + u.deltaSymbol : "";
    if (*d == 0.0) return "±0" + suffix;
    char format[16];
    std::snprintf(format, sizeof format, "%%+.%df", u.decimals);
    return printf1(format, shown(unit, *d)) + suffix;
}

nlohmann::ordered_json figureJson(FigureUnit unit, std::optional<double> v) {
    if (!v || !std::isfinite(*v)) return nullptr;
    if (unit == FigureUnit::Bytes || unit == FigureUnit::Count) return static_cast<long long>(std::llround(*v));
    return *v;
}

std::string jsonPointer(const std::string& key) {
    std::string pointer = "/" + key;
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    return pointer;
}

std::vector<FigureValue> readFigures(const PresetMeasurement& m, Shows s, const FigureTable& table) {
    std::vector<FigureValue> out;
    for (const FigureRow* r : figuresShown(s, table)) out.push_back({r, r->read(m)});
    return out;
}

std::string figuresMarkdown(const FigureTable& table) {
    std::string md =
        "# Figures\n\n"
        "<!-- Generated from metrics/figure_table.cpp by st_figures_doc; do not edit. Regenerate with\n"
        "     cmake --build <build dir> --target st_update_metrics_doc -->\n\n"
        "Every figure the product reports, from the one table of figures (`metrics/figure_table.cpp`).\n"
        "The key is the figure's name everywhere: its path in `metrics.json` and `compare.json`, and its\n"
        "column in a sweep's `results.csv` and `results.json`. Those files hold the raw value (a share as a\n"
        "fraction 0..1, bytes as bytes); tables, charts and panels show it in the unit below. A figure that\n"
        "does not apply (flicker without a camera path, cost when it was not measured) is `null` in JSON\n"
        "and empty in CSV.\n\n"
        "Choice: the name `shadowtune sweep --error NAME` (or `--cost NAME`) takes for the figure.\n\n"
        "## Units\n\n| unit | raw value | shown as |\n|---|---|---|\n";
    for (const FigureUnit u : {FigureUnit::Share, FigureUnit::Error, FigureUnit::PxPerTexel, FigureUnit::Px,
                               FigureUnit::Ms, FigureUnit::Bytes, FigureUnit::Count}) {
        const UnitInfo& i = unitInfo(u);
        md += std::string("| ") + i.name + " | " + i.raw + " | " + i.shownAs + " |\n";
    }
    std::string group;
    for (const FigureRow& r : table) {
        const std::string g = r.key.substr(0, r.key.find('.'));
        if (g != group) {
            group = g;
            md += "\n## " + sectionTitle(g) +
                  "\n\n| key | label | unit | better | choice | where | description |\n|---|---|---|---|---|---|---|\n";
        }
        md += "| `" + r.key + "` | " + cell(r.label) + " | " + unitInfo(r.unit).name + " | " + betterName(r.better) +
              " | " + (r.choice.empty() ? "" : "`" + r.choice + "`") + " | " + whereShown(r) + " | " +
              cell(r.description) + (r.timing ? " Measured: differs between runs." : "") + " |\n";
    }
    return md;
}

}  // namespace st::metrics
