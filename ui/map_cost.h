#pragma once
// Issue 11 #7: a map-size change that would take more than a stated memory or redraw time asks
// first. The cost of a cascade setup (the bytes the renderer allocates, the redraw time scaled from
// the last measured shadow pass) and the change held while the editor asks.
#include "renderer/render/frame_stats.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace st::ui {

// Above 256 MiB of depth maps an allocation is a visible stall on the 2-core llvmpipe machine
// and a large share of an integrated GPU's memory: 4 x 4096 maps (256 MiB) still apply at once,
// 4 x 8192 (1 GiB) asks.
inline constexpr std::size_t kAskAboveShadowBytes = std::size_t{256} << 20;
// A redraw longer than a quarter second stops the editor feeling interactive (issue 11: 8192 maps
// ran at 1.6 s per frame "with no warning"); it asks above that.
inline constexpr double kAskAboveRedrawMs = 250.0;

// Issue 39 #7: a 4096 map's confirmation said ~313 ms a redraw, and the first frame took 3.3 s.
// The estimate scaled the shadow pass's timers alone, which on llvmpipe bracket only part of the
// pass, and left out the rest of the frame (the main pass) and the first frame's making of the maps:
// allocating and clearing new depth textures, in proportion to their texels. Measured with
// tests/bench/map_change_bench on truck-town (4 x 2048 -> 4 x 4096, 1280x720, 2 cores at load 4.8):
// the first frame 141 ms over a later redraw, a D32F array allocated and cleared alone 145 ms, both
// 2.2 ns per texel (docs/editor.md#large-maps).
inline constexpr double kFirstFrameNsPerTexel = 2.2;

// What a cascade setup costs: the bytes of csm::planStorage's textures (nullopt when the storage
// refuses the setup, which validation reports), the estimated redraw time of its shadow pass
// (nullopt: nothing measured yet; what asks first), the whole frame's redraw and the first frame's.
struct MapCost {
    std::optional<std::size_t> bytes;
    std::optional<double> redrawMs;
    bool modelled = false;  // redrawMs comes from the cost model, no shadow pass having been timed
    std::optional<double> frameMs;       // the whole frame, from the last full frame (FrameBase)
    std::optional<double> firstFrameMs;  // frameMs (else redrawMs) + making the maps
};

// The last full-quality frame: its wall time and its maps' texels. A redraw of other maps is that
// frame with its shadow pass rescaled: the main pass and the rest stay as they were.
struct FrameBase {
    double wallMs = 0.0;
    double texels = 0.0;
};

// The first frame of a new storage: a redraw plus making `newTexels` of maps.
double firstFrameMs(double redrawMs, double newTexels);

// Texels of every cascade's map (csm::cascadeMapSize each), the quantity the redraw time scales with.
double cascadeTexels(const CascadeSettings& c);

// Milliseconds per texel of the cascades `stats` says were redrawn (their gpuMs over their
// texels; a cascade's size from the stats, else from `rendered`); nullopt when none was redrawn
// with a measured time.
std::optional<double> measuredMsPerTexel(const FrameStats& stats, const CascadeSettings& rendered);

// The same rate from the app's cost model (FrameStats::modelShadowMs, every map redrawn), for a
// session whose shadow passes were never timed: the 8192 prompt then still says what the redraw
// costs (issue 21 #12). nullopt when the frame was not modelled.
std::optional<double> modelledMsPerTexel(const FrameStats& stats, const CascadeSettings& rendered);

MapCost mapCost(const CascadeSettings& c, std::optional<double> msPerTexel, bool modelled = false,
                std::optional<FrameBase> base = std::nullopt);

// Whether going from `before` to `after` asks first: a limit is exceeded and that figure grows
// (a change that lowers a cost already over the limit applies at once).
bool asksFirst(const MapCost& before, const MapCost& after);

// "4 x 8192 maps: 1.00 GiB of shadow maps; the first frame about 3.6 s while the maps are made,
// then about 1.6 s a redraw on this machine. Apply?"
std::string costQuestion(const CascadeSettings& c, const MapCost& cost);

// The fields whose change can grow the shadow maps.
bool affectsMapCost(std::string_view path);

// The edit held while the modal asks, and the last measured redraw rate (kept across frames
// whose cascades were all cached, which measure nothing).
struct MapCostAsk {
    const FieldInfo* field = nullptr;  // nullptr: nothing held
    FieldValue value;
    std::string question;
    bool open = false;                 // open the modal this frame
    std::optional<double> msPerTexel;
    bool modelled = false;             // msPerTexel is the cost model's, nothing measured yet
    std::optional<FrameBase> base;     // the last full-quality frame seen
};

}  // namespace st::ui
