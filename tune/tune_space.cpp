#include "tune/tune_space.h"

#include "renderer/csm/cascade_plan.h"
#include "renderer/settings/cascade_factors.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/settings_json.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <optional>

namespace st::tune {
namespace {
using Json = nlohmann::json;

// "bias.constantScale[2]": a list field's element (the per-cascade bias factors).
struct Element {
    std::string list;
    std::size_t index = 0;
};
std::optional<Element> elementOf(const std::string& path) {
    const std::size_t open = path.find('[');
    if (open == std::string::npos || path.back() != ']') return std::nullopt;
    return Element{path.substr(0, open), std::size_t(std::stoul(path.substr(open + 1, path.size() - open - 2)))};
}

const FieldInfo& field(const std::string& path) {
    const FieldInfo* f = findField(path);
    if (!f) throw SettingsError("tune: no settings field " + path);
    return *f;
}

std::vector<Json> enumValues(const std::string& path) {
    std::vector<Json> out;
    for (std::string_view name : field(path).enumNames) out.emplace_back(std::string(name));
    return out;
}

template <class T>
std::vector<Json> list(std::initializer_list<T> values) {
    return {values.begin(), values.end()};
}

}  // namespace

double farPlaneShare(const Settings& s, double share) { return std::round(double(s.camera.farPlane) * share * 10.0) / 10.0; }

const Dimension* Space::find(const std::string& path) const {
    for (const Dimension& d : dims)
        if (d.path == path) return &d;
    return nullptr;
}

Space defaultSpace(const Settings& base) {
    Space s;
    auto add = [&](std::string path, std::vector<Json> values) { s.dims.push_back({std::move(path), std::move(values)}); };
    add("cascades.count", list({1, 2, 3, 4, 5, 6}));
    if (base.cascades.scheme == SplitScheme::Manual) add("cascades.scheme", list<std::string>({"manual", "practical"}));
    add("cascades.lambda", list({0.3, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 0.98}));
    // Shadow distance as shares of the far plane: a scene's useful range is not known in metres.
    std::vector<Json> distances{0.0};
    for (double share : {0.8, 0.65, 0.5, 0.4, 0.3, 0.22, 0.15, 0.12, 0.1, 0.08, 0.065})
        distances.emplace_back(farPlaneShare(base, share));
    add("cascades.shadowDistance", distances);
    s.dims.back().jumps = true;
    add("cascades.depthBounds", enumValues("cascades.depthBounds"));
    add("cascades.fit", enumValues("cascades.fit"));
    add("cascades.zExtension", list<std::string>({"scene-bounds", "distance", "pancake", "none"}));
    // A fixed reach toward the light, as shares of the far plane like the depths above: casters
    // taller than the scene's receivers need little of it, and scene-bounds draws the whole column
    // (truck-town, sample fit: 2.75 M fragments in the nearest map against 2.03 M at 50-300 m).
    std::vector<Json> reaches;
    for (double share : kZExtensionShares) reaches.emplace_back(farPlaneShare(base, share));
    add("cascades.zExtensionDistance", reaches);
    add("cascades.stabilize", list({false, true}));
    // Map selection reads the finest map that holds the pixel: a cascade's box reaches past its
    // split, so pixels there get its finer texels at no cost (truck-town: px/texel 1.90 -> 0.87).
    add("cascades.selection", enumValues("cascades.selection"));
    add("cascades.mapSize", list({256, 512, 1024, 2048, 4096}));
    add("cascades.storage", enumValues("cascades.storage"));
    // Per cascade: a map size (atlas and textures storage) and each split depth, as shares of the
    // far plane on a roughly geometric ladder (splits crowd near the camera).
    std::vector<Json> splitDepths;
    for (double share : {0.002, 0.004, 0.006, 0.01, 0.015, 0.02, 0.03, 0.04, 0.06, 0.08, 0.1, 0.13, 0.17, 0.22, 0.3,
                         0.4, 0.5, 0.65, 0.8})
        splitDepths.emplace_back(farPlaneShare(base, share));
    for (int i = 0; i < kMaxTunedCascades; ++i) {
        s.dims.push_back({"cascades.mapSizes[" + std::to_string(i) + "]", list({256, 512, 1024, 2048, 4096}), true});
        if (i + 1 < kMaxTunedCascades)
            s.dims.push_back({"cascades.manualSplits[" + std::to_string(i) + "]", splitDepths, true});
    }
    add("cascades.blendBand", list({0.0, 0.05, 0.1, 0.2}));
    add("cascades.fadeBand", list({0.0, 0.1, 0.2}));
    add("filter.kind", enumValues("filter.kind"));
    add("filter.size", list({3, 5, 7, 9}));
    add("filter.blurRadius", list({0, 1, 2, 3, 4}));
    add("filter.pcssMaxRadius", list({2.0, 4.0, 8.0, 12.0, 16.0}));
    add("filter.contact", enumValues("filter.contact"));
    add("filter.contactLength", list({0.1, 0.25, 0.5, 1.0, 2.0}));
    add("bias.constant", list({0.0, 0.0025, 0.005, 0.01, 0.015, 0.02, 0.03, 0.05, 0.08}));
    add("bias.slope", list({0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0}));
    add("bias.normalOffset", list({0.0, 0.25, 0.5, 0.75, 1.0, 1.5}));
    add("bias.receiverPlane", list({false, true}));
    // Bias per cascade: factors of the global constant and slope (bias.constantScale, slopeScale).
    for (int i = 0; i < kMaxTunedCascades; ++i) {
        add("bias.constantScale[" + std::to_string(i) + "]", list({0.25, 0.5, 1.0, 1.5, 2.0, 3.0}));
        add("bias.slopeScale[" + std::to_string(i) + "]", list({0.25, 0.5, 1.0, 1.5, 2.0, 3.0}));
    }
    // What a tune's end polishes: the depths and the bias, not the structure (filter.kind may
    // change what the maps hold).
    for (Dimension& d : s.dims) {
        const auto starts = [&](const char* prefix) { return d.path.rfind(prefix, 0) == 0; };
        d.polish = starts("bias.") || (starts("filter.") && d.path != "filter.kind") || starts("cascades.manualSplits") ||
                   d.path == "cascades.shadowDistance" || d.path == "cascades.blendBand" || d.path == "cascades.fadeBand";
    }
    return s;
}

namespace {

// The interior split depths `s` renders with its scheme, before depth bounds move them: where a
// move of one manual split starts from when the preset computes its splits.
std::vector<float> interiorSplits(const Settings& s) {
    std::vector<float> z;
    try {
        z = csm::planSplits(s, std::nullopt);  // no depth range seen: the scheme's own splits
    } catch (const std::invalid_argument& e) {
        throw SettingsError(std::string("tune: ") + e.what());
    }
    return {z.begin() + 1, z.end() - 1};
}

std::vector<int> mapSizesOf(const CascadeSettings& c) {
    return c.mapSizes.empty() ? std::vector<int>(std::size_t(c.count), c.mapSize) : c.mapSizes;
}

// One element of a per-cascade list: a split depth (the preset turns manual, its other splits
// where they were), a map size (the others at the size they had), or a bias factor.
Settings withElement(Settings s, const Element& e, const nlohmann::json& value, const std::string& path) {
    const std::string noCascade = path + ": no cascade " + std::to_string(e.index);
    if (e.list == "cascades.manualSplits") {
        std::vector<float> splits = interiorSplits(s);
        if (e.index >= splits.size()) throw SettingsError(noCascade);
        splits[e.index] = value.get<float>();
        s.cascades.scheme = SplitScheme::Manual;
        s.cascades.manualSplits = splits;
        return s;
    }
    if (e.list == "cascades.mapSizes") {
        std::vector<int> sizes = mapSizesOf(s.cascades);
        if (e.index >= sizes.size()) throw SettingsError(noCascade);
        sizes[e.index] = value.get<int>();
        s.cascades.mapSizes = sizes;
        return s;
    }
    const FieldInfo& f = field(e.list);
    auto factors = std::get<std::vector<float>>(f.get(s));
    if (factors.empty()) factors.assign(std::size_t(s.cascades.count), 1.0f);  // every cascade at the global bias
    if (e.index >= factors.size()) throw SettingsError(noCascade);
    factors[e.index] = value.get<float>();
    f.set(s, factors);
    return s;
}

}  // namespace

Settings withFieldJson(Settings s, const std::string& path, const nlohmann::json& value) {
    if (const std::optional<Element> e = elementOf(path)) return withElement(std::move(s), *e, value, path);
    const FieldInfo& f = field(path);
    const int sizeBefore = s.cascades.mapSize;
    f.set(s, readFieldValue(f, value, path));
    keepCascadeListsValid(s, path);
    // The size of every map: per-cascade sizes keep their ratios (within the field's limits).
    if (path == "cascades.mapSize")
        for (int& size : s.cascades.mapSizes)
            size = std::clamp(int(std::int64_t(size) * s.cascades.mapSize / sizeBefore), 256, 8192);
    // Manual splits are one per cascade boundary: another count, or a weight, means computed splits.
    const bool manual = s.cascades.scheme == SplitScheme::Manual;
    if (manual && (path == "cascades.lambda" || s.cascades.manualSplits.size() != std::size_t(s.cascades.count - 1))) {
        s.cascades.scheme = SplitScheme::Practical;
        s.cascades.manualSplits.clear();
    }
    return s;
}

Settings withValue(Settings s, const Dimension& d, std::size_t i) { return withFieldJson(std::move(s), d.path, d.values.at(i)); }

Json currentValue(const Settings& s, const Dimension& d) {
    if (const std::optional<Element> e = elementOf(d.path)) {
        if (e->list == "cascades.manualSplits") {
            const std::vector<float> splits = interiorSplits(s);
            return e->index < splits.size() ? Json(double(splits[e->index])) : Json(nullptr);
        }
        if (e->list == "cascades.mapSizes") {
            const std::vector<int> sizes = mapSizesOf(s.cascades);
            return e->index < sizes.size() ? Json(sizes[e->index]) : Json(s.cascades.mapSize);
        }
        const auto factors = std::get<std::vector<float>>(field(e->list).get(s));
        return e->index < factors.size() ? Json(double(factors[e->index])) : Json(1.0);
    }
    const FieldInfo& f = field(d.path);
    return fieldValueToJson(f, f.get(s));
}

std::size_t currentIndex(const Settings& s, const Dimension& d) {
    const Json now = currentValue(s, d);
    std::size_t best = 0;
    double bestGap = INFINITY;
    for (std::size_t i = 0; i < d.values.size(); ++i) {
        if (d.values[i] == now) return i;
        if (now.is_number() && d.values[i].is_number()) {
            const double gap = std::abs(d.values[i].get<double>() - now.get<double>());
            if (gap < bestGap) bestGap = gap, best = i;
        }
    }
    return best;
}

bool applies(const Settings& s, const std::string& path) {
    if (const std::optional<Element> e = elementOf(path)) {
        // A split moves a computed scheme's splits too (the preset turns manual).
        if (e->list == "cascades.manualSplits") return int(e->index) < s.cascades.count - 1;
        return int(e->index) < s.cascades.count && fieldApplies(s, path);
    }
    return fieldApplies(s, path);
}

std::vector<Change> changesBetween(const Settings& from, const Settings& to) {
    std::vector<Change> out;
    for (const FieldInfo* f : changedFields(from, to))
        out.push_back({std::string(f->path), fieldValueToJson(*f, f->get(from)), fieldValueToJson(*f, f->get(to))});
    return out;
}

}  // namespace st::tune
