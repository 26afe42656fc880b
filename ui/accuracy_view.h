#pragma once
// What the Accuracy panel shows, as plain values: the app turns its background ground-truth job
// (metrics/) into these, so ui/ needs neither the metrics layer nor GL. Figures follow
// docs/architecture.md#how-the-product-is-measured and the `measure` command's summary.
#include <cstddef>
#include <string>
#include <vector>

namespace st::ui {

// The Accuracy panel's overlay toggle (off by default, issue 39 #3): its label and tooltip say what
// the overlay's colours mean, so it is found and read without the docs.
inline constexpr const char* kErrorOverlayLabel = "Show errors on the scene";
inline constexpr const char* kErrorOverlayTooltip =
    "Paints the measured errors over the shaded view (off by default).\n"
    "Magenta: false shadow, the map shadows what the sun lights (acne, shadows too wide).\n"
    "Cyan: false light, the map lights what is in shadow (leaks, peter-panning, missing casters).\n"
    "Pale: within the edge band (what the map's resolution explains); saturated with a ring: gross.\n"
    "Shown over the main view only, and only while it is the frame that was measured.";

// Pixel counts of one group of pixels (the frame, one cascade, or beyond the shadow range).
struct AccuracyCounts {
    std::size_t receivers = 0;  // sun-facing pixels: the denominator of every share
    std::size_t falseShadowEdge = 0;
    std::size_t falseShadowGross = 0;
    std::size_t falseLightEdge = 0;
    std::size_t falseLightGross = 0;
    double filteredError = 0.0;  // mean |filtered factor - truth|

    std::size_t falseShadow() const { return falseShadowEdge + falseShadowGross; }
    std::size_t falseLight() const { return falseLightEdge + falseLightGross; }
    std::size_t edge() const { return falseShadowEdge + falseLightEdge; }
    std::size_t gross() const { return falseShadowGross + falseLightGross; }
    std::size_t misclassified() const { return falseShadow() + falseLight(); }
    double share(std::size_t count) const { return receivers ? double(count) / double(receivers) : 0.0; }
};

// The filtered result against the soft truth of the sun's disc (metrics/soft_accuracy.h).
struct SoftAccuracyCounts {
    float angularDiameter = 0.0f;  // degrees
    int rays = 0;
    std::size_t receivers = 0;
    double filteredError = 0.0;  // mean |filtered factor - visible fraction of the disc|
    std::size_t acne = 0, lightBleeding = 0, peterPanning = 0, missingCaster = 0, edge = 0;
    double penumbraTruthPx = 0.0, penumbraFilteredPx = 0.0;  // mean widths
    double share(std::size_t count) const { return receivers ? double(count) / double(receivers) : 0.0; }
};

// One figure line of the panel, from the figure table (metrics/figure_table.h), ready to show.
struct FigureLine {
    std::string key;          // "accuracy.misclassified": its group is the part before the first dot
    std::string label;        // "misclassified"
    std::string value;        // "1.234 %"
    std::string description;  // the hover text
};

struct AccuracyView {
    enum class State {
        Off,        // the app computes nothing (the panel was never shown)
        Settling,   // waiting for the camera and settings to stay still
        Computing,  // ground truth running in the background
        Done,       // figures below describe the frame on screen
        Failed,     // `error` says why
    };
    State state = State::Off;
    float progress = 0.0f;      // Computing: 0..1
    std::string phase;          // Computing: "building the BVH", "casting rays", ...
    double seconds = 0.0;       // Done: read-back to result, wall time
    std::string timing;         // Done: where the time went, one line
    std::string error;          // Failed
    int width = 0, height = 0;  // Done: pixels measured (the scene view)
    AccuracyCounts all;
    std::vector<AccuracyCounts> cascades;
    AccuracyCounts beyond;      // past the shadow distance: drawn lit
    std::vector<std::string> warnings;  // Done: wasted maps, each with its likely fix (metrics/map_warnings.h)
    SoftAccuracyCounts soft;
    std::vector<FigureLine> figures;  // Done: the table's Accuracy-panel rows, in table order
};

}  // namespace st::ui
