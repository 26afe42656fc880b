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

// What a cascade setup costs: the bytes of csm::planStorage's textures (nullopt when the storage
// refuses the setup, which validation reports) and the estimated redraw time (nullopt: nothing
// measured yet).
struct MapCost {
    std::optional<std::size_t> bytes;
    std::optional<double> redrawMs;
    bool modelled = false;  // redrawMs comes from the cost model, no shadow pass having been timed
};

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

MapCost mapCost(const CascadeSettings& c, std::optional<double> msPerTexel, bool modelled = false);

// Whether going from `before` to `after` asks first: a limit is exceeded and that figure grows
// (a change that lowers a cost already over the limit applies at once).
bool asksFirst(const MapCost& before, const MapCost& after);

// "4 x 8192 maps: 1.00 GiB of shadow maps, about 1.6 s per redraw on this machine. Apply?"
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
};

}  // namespace st::ui
