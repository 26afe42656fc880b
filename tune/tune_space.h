#pragma once
// What `shadowtune tune` may change (docs/tuning.md): every setting that changes the shadow
// result, each as an ordered list of candidate values, so "a neighbour" of a value is the next
// one up or down the list. Pure settings code, no GL.
#include "renderer/settings/settings.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace st::tune {

// Bias factors per cascade are tuned for the first this many cascades (the space's count goes to 6).
inline constexpr int kMaxTunedCascades = 6;

// cascades.zExtensionDistance's candidates as shares of the camera's far plane; the tuner's
// sample-fit starts take kZExtensionStartShare as their reach (and seenNear as its shadow distance).
inline constexpr double kZExtensionShares[] = {0.01, 0.02, 0.035, 0.05, 0.1, 0.2, 0.4};
inline constexpr double kZExtensionStartShare = 0.1;

// A share of `s`'s far plane in metres, to a tenth of a metre: how the space states depths and
// distances, since a scene's useful range is not known in metres.
double farPlaneShare(const Settings& s, double share);

// One knob: a field of the settings table (renderer/settings/field_table.h) and its candidates.
struct Dimension {
    std::string path;                   // "cascades.lambda", or a list element: "bias.constantScale[1]"
    std::vector<nlohmann::json> values;  // in order: neighbours are adjacent
    // A refinement (one cascade's map size or split depth): tried only once no move of the
    // others helps, so the many per-cascade moves do not spend the evaluations a descent of
    // the whole preset needs first.
    bool refinement = false;
    // A range whose far values matter as much as the near ones (the shadow distance: a tenth of
    // the far plane is four steps from none): every value is a move, the best screened first.
    bool jumps = false;
    // A fine move of a settled point (shadow distance, split depths, bias, filter parameters,
    // bands): tried again, each evaluated in full, from the best point at the end
    // (SearchOptions::polish).
    bool polish = false;
};

struct Space {
    std::vector<Dimension> dims;
    // When set, every point the search screens or evaluates is first put through it: an engine's
    // space (tune_engine.h) maps a move onto what the engine can take (Godot: 1, 2 or 4 splits,
    // its bias per split), so the search never scores settings the engine cannot set.
    std::function<Settings(const Settings&)> project;
    const Dimension* find(const std::string& path) const;
};

// The default space for tuning `base`: split count, scheme weight, shadow distance (fractions of
// the base's far plane), depth bounds and sample fit, fit, z-extension, stabilisation, storage,
// reach toward the light with a distance z-extension, map size, filter kind and its parameters, bias constant, slope, normal offset and
// receiver-plane, blend and fade bands, bias per cascade; as refinements, each cascade's map size
// (atlas and textures storage) and each split depth (a computed scheme turns manual). Fields that only time-slice work (updateInterval) are
// left out: the cost model prices a frame with every map redrawn, so they would look free.
Space defaultSpace(const Settings& base);

// `s` with the field at `path` set to `value` (its JSON form); a manual-split preset whose count
// or weight changes gets computed (practical) splits. Throws SettingsError for a value the field
// rejects.
Settings withFieldJson(Settings s, const std::string& path, const nlohmann::json& value);
// `s` with dimension `d` set to its i-th value (through the field table, as a sweep's "set" is).
// Throws SettingsError for a value the field rejects.
Settings withValue(Settings s, const Dimension& d, std::size_t i);
// The index of the candidate equal to (or, for numbers, nearest to) `s`'s current value.
std::size_t currentIndex(const Settings& s, const Dimension& d);
// `s`'s value of `d` as JSON (the field table's JSON form).
nlohmann::json currentValue(const Settings& s, const Dimension& d);

// Whether `d` changes what settings `s` render (renderer/settings/kind_descriptors.h:
// filter.size only for PCF NxN and PCSS, moment parameters only for moment kinds, a cascade's
// bias factor only for a cascade that exists, ...). A move along one that does not is not worth
// an evaluation.
bool applies(const Settings& s, const std::string& path);

// Every field whose value differs between `from` and `to`, in the field table's order.
struct Change {
    std::string path;
    nlohmann::json from, to;
};
std::vector<Change> changesBetween(const Settings& from, const Settings& to);

}  // namespace st::tune
