#include "renderer/settings/kind_descriptors.h"

#include "renderer/settings/enum_names.h"

#include <algorithm>
#include <array>

namespace st {
namespace {

using Reads = std::vector<std::string_view>;

// The depth-compare kinds put the receiver's plane under every texel they compare
// (shaders/shadow_sampling.glsl sampleCascade); the moment kinds compare no texel depths.
constexpr std::string_view kReceiverPlane = "bias.receiverPlane";
const Reads kMomentReads{"filter.blurRadius", "filter.mipmaps", "filter.moments16", "filter.bleedExponent", "filter.bleedLow",
                         "filter.bleedHigh"};

Reads plus(Reads a, const Reads& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// shaders/shadow_sampling.glsl and moments.glsl: what each filter reads of the CascadeBlock.
// PCSS spreads filter.size^2 taps with the NxN filter's weights (pcfWeights) over its penumbra.
// The moment maps are one array of one layer per cascade (renderer/render/moment_maps.h); PCSS's
// blocker search reads raw depths from the one depth texture of the array or the atlas.
std::vector<KindDescriptor> filterKinds() {
    using S = CascadeStorage;
    const std::vector<S> arrayOnly{S::Array};
    return {
        {ST_FILTER_HARD, "", {kReceiverPlane}, {}},
        {ST_FILTER_PCF2X2, "", {kReceiverPlane}, {}},
        {ST_FILTER_PCF_NXN, "", {"filter.size", "filter.weights", kReceiverPlane}, {}},
        {ST_FILTER_VSM, "", plus(kMomentReads, {"filter.minVariance"}), arrayOnly},
        {ST_FILTER_EVSM2, "", plus(kMomentReads, {"filter.minVariance", "filter.evsmPositive"}), arrayOnly},
        {ST_FILTER_EVSM4, "", plus(kMomentReads, {"filter.minVariance", "filter.evsmPositive", "filter.evsmNegative"}),
         arrayOnly},
        {ST_FILTER_MSM, "", plus(kMomentReads, {"filter.momentBias"}), arrayOnly},
        {ST_FILTER_PCSS, "",
         {"filter.size", "filter.weights", "filter.blockerTaps", "filter.pcssMaxRadius", kReceiverPlane},
         {S::Array, S::Atlas}},
        {ST_FILTER_VOGEL, "", {"filter.vogelTaps", "filter.radius", kReceiverPlane}, {}},
        {ST_FILTER_TENT, "", {"filter.size", kReceiverPlane}, {}},
    };
}

// renderer/csm/storage_layout.h: an array has one size for every layer and no tiles to pad.
std::vector<KindDescriptor> storageKinds() {
    return {
        {ST_STORAGE_ARRAY, "", {}, {}},
        {ST_STORAGE_ATLAS, "", {"cascades.mapSizes", "cascades.atlasPadding"}, {}},
        {ST_STORAGE_TEXTURES, "", {"cascades.mapSizes"}, {}},
    };
}

// Both selections read the blend band (by depth, or by distance to the tile's edge) and the
// filter's edge margin through the kinds' own fields, so neither gates a field of its own.
std::vector<KindDescriptor> selectionKinds() {
    return {{ST_SELECT_INTERVAL, "", {}, {}}, {ST_SELECT_MAP, "", {}, {}}};
}

std::vector<KindDescriptor> schemeKinds() {
    return {{ST_SPLIT_UNIFORM, "", {}, {}},
            {ST_SPLIT_LOGARITHMIC, "", {}, {}},
            {ST_SPLIT_PRACTICAL, "", {"cascades.lambda"}, {}},
            {ST_SPLIT_MANUAL, "", {"cascades.manualSplits"}, {}}};
}

std::vector<KindDescriptor> zExtensionKinds() {
    return {{ST_ZEXT_NONE, "", {}, {}},
            {ST_ZEXT_DISTANCE, "", {"cascades.zExtensionDistance"}, {}},
            {ST_ZEXT_SCENE_BOUNDS, "", {}, {}},
            {ST_ZEXT_PANCAKE, "", {"cascades.pancakeToCasters"}, {}}};
}

std::vector<KindDescriptor> screenKinds() {
    return {{ST_SCREEN_OFF, "", {}, {}},
            {ST_SCREEN_BLUR, "", {"filter.screenDownsample", "filter.screenBlurRadius", "filter.screenDepthSigma"}, {}}};
}

std::vector<KindDescriptor> contactKinds() {
    return {{ST_CONTACT_OFF, "", {}, {}},
            {ST_CONTACT_MARCH, "", {"filter.contactLength", "filter.contactSteps", "filter.contactThickness"}, {}}};
}

std::vector<KindDescriptor> viewKinds() {
    std::vector<KindDescriptor> kinds;
    for (int v = 0; v < ST_VIEW_COUNT; ++v) kinds.push_back({v, "", {}, {}});
    kinds[ST_VIEW_TEXEL_GRID].reads = {"output.texelBlock"};
    kinds[ST_VIEW_SIDE].reads = {"output.sideTexels"};
    return kinds;
}

template <class E>
ModeDescriptor mode(std::string_view field, std::vector<KindDescriptor> kinds) {
    ModeDescriptor m{field, {}, std::move(kinds)};
    for (KindDescriptor& k : m.kinds) {
        k.name = enumNames<E>()[static_cast<std::size_t>(k.value)];
        for (std::string_view read : k.reads)
            if (std::find(m.gates.begin(), m.gates.end(), read) == m.gates.end()) m.gates.push_back(read);
    }
    return m;
}

std::vector<ModeDescriptor> buildModes() {
    return {
        mode<FilterKind>("filter.kind", filterKinds()),
        mode<ScreenSpace>("filter.screenSpace", screenKinds()),
        mode<ContactShadows>("filter.contact", contactKinds()),
        mode<SplitScheme>("cascades.scheme", schemeKinds()),
        mode<ZExtension>("cascades.zExtension", zExtensionKinds()),
        mode<CascadeStorage>("cascades.storage", storageKinds()),
        mode<Selection>("cascades.selection", selectionKinds()),
        mode<View>("output.view", viewKinds()),
    };
}

// The mode field's current value in `s`.
int modeValue(const Settings& s, const ModeDescriptor& m) { return std::get<int>(findField(m.field)->get(s)); }

// The kinds of mode `m` that read `path`, as "evsm2 and evsm4" for messages.
std::string readersText(const ModeDescriptor& m, std::string_view path) {
    std::vector<std::string_view> names;
    for (const KindDescriptor& k : m.kinds)
        if (std::find(k.reads.begin(), k.reads.end(), path) != k.reads.end()) names.push_back(k.name);
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) text += (i + 1 == names.size()) ? " and " : ", ";
        text += names[i];
    }
    return text;
}

std::string gatedReason(const Settings& s, std::string_view path) {
    for (const ModeDescriptor& m : modeDescriptors()) {
        if (std::find(m.gates.begin(), m.gates.end(), path) == m.gates.end()) continue;
        const int value = modeValue(s, m);
        if (value < 0 || static_cast<std::size_t>(value) >= m.kinds.size()) continue;  // validation names it
        const KindDescriptor& k = m.kinds[static_cast<std::size_t>(value)];
        if (std::find(k.reads.begin(), k.reads.end(), path) != k.reads.end()) continue;
        return "Used with " + std::string(m.field) + " " + readersText(m, path) + " only (now " + std::string(k.name) +
               ").";
    }
    return {};
}

// A per-cascade scale multiplies its bias: while that bias is 0 no scale changes anything.
std::string scaleReason(const Settings& s, std::string_view path) {
    struct Scale {
        std::string_view path, bias;
        float value;
    };
    const std::array<Scale, 3> scales{{{"bias.constantScale", "bias.constant", s.bias.constant},
                                       {"bias.slopeScale", "bias.slope", s.bias.slope},
                                       {"bias.normalOffsetScale", "bias.normalOffset", s.bias.normalOffset}}};
    for (const Scale& sc : scales)
        if (path == sc.path && sc.value == 0.0f) return "Scales " + std::string(sc.bias) + ", which is 0.";
    return {};
}

std::string numericReason(const Settings& s, std::string_view path) {
    if (path == "notes") return "Free text: nothing reads it.";
    if (path == "cascades.blendBand" && s.cascades.count < 2) return "Blends one cascade into the next: needs two or more.";
    const bool splitField = path == "cascades.scheme" || path == "cascades.lambda" || path == "cascades.manualSplits";
    if (splitField && s.cascades.count < 2) return "One cascade has no split to place: it spans the whole range.";
    return scaleReason(s, path);
}

constexpr std::string_view kIndependent[] = {
    "scene", "notes", "ground", "origin", "camera.position", "camera.target", "camera.fovY", "camera.nearPlane",
    "camera.farPlane", "light.azimuth", "light.elevation", "light.intensity", "light.ambient",
    "light.angularDiameter", "cascades.count", "cascades.shadowDistance", "cascades.depthBounds",
    "cascades.mapSize", "cascades.fit", "cascades.stabilize", "cascades.casterCulling", "cascades.updateInterval",
    "cascades.blendBand", "cascades.fadeBand", "cascades.cameraRelative", "cascades.fitFovY",
    "cascades.matricesOneFrameLate", "cascades.lightDepth", "cascades.casterFaces", "cascades.snap", "cascades.sliceCorners", "cascades.sphereCentre", "bias.constantUnit", "filter.padding", "bias.constant",
    "bias.slope", "bias.normalOffset", "bias.normalOffsetUnit", "bias.normalOffsetSide", "bias.constantScale", "bias.slopeScale", "bias.normalOffsetScale", "output.width",
    "output.height", "path.frames", "path.keyframes", "measure.sunRays", "measure.artifactTexels",
    // The mode fields themselves: each one always applies.
    "filter.kind", "filter.screenSpace", "filter.contact", "cascades.scheme", "cascades.zExtension", "cascades.storage",
    "cascades.selection", "output.view"};

// Not shadow settings: what is shadowed, seen, shown or measured, or free text; caster culling,
// which only skips casters that cannot reach the image (the image stays the same); and the
// one-frame-late matrices, a bug reproduced on purpose, never a choice to tune.
bool isShadowSetting(std::string_view path) {
    if (path.starts_with("cascades.") || path.starts_with("filter.") || path.starts_with("bias."))
        return path != "cascades.casterCulling" && path != "cascades.matricesOneFrameLate";
    return false;
}

const KindDescriptor& kindOf(std::string_view modeField, int value) {
    return findMode(modeField)->kinds.at(static_cast<std::size_t>(value));
}

}  // namespace

const std::vector<ModeDescriptor>& modeDescriptors() {
    static const std::vector<ModeDescriptor> modes = buildModes();
    return modes;
}

const ModeDescriptor* findMode(std::string_view modeField) {
    const auto& modes = modeDescriptors();
    const auto it = std::find_if(modes.begin(), modes.end(), [&](const ModeDescriptor& m) { return m.field == modeField; });
    return it == modes.end() ? nullptr : &*it;
}

const KindDescriptor& describe(FilterKind kind) { return kindOf("filter.kind", shaderCode(kind)); }
const KindDescriptor& describe(CascadeStorage storage) { return kindOf("cascades.storage", shaderCode(storage)); }
const KindDescriptor& describe(Selection selection) { return kindOf("cascades.selection", shaderCode(selection)); }

std::span<const std::string_view> kindIndependentFields() { return kIndependent; }

std::string notApplicableReason(const Settings& s, std::string_view path) {
    path = path.substr(0, path.find('['));
    if (!findField(path)) return "Not a field of the settings table.";
    std::string reason = gatedReason(s, path);
    return reason.empty() ? numericReason(s, path) : reason;
}

bool fieldApplies(const Settings& s, std::string_view path) { return notApplicableReason(s, path).empty(); }

std::vector<const FieldInfo*> applicableFields(const Settings& s) {
    std::vector<const FieldInfo*> fields;
    for (const FieldInfo& f : fieldTable())
        if (fieldApplies(s, f.path)) fields.push_back(&f);
    return fields;
}

std::vector<const FieldInfo*> tunableFields(const Settings& s) {
    std::vector<const FieldInfo*> fields = applicableFields(s);
    std::erase_if(fields, [](const FieldInfo* f) { return !isShadowSetting(f->path); });
    return fields;
}

bool storageSupports(FilterKind kind, CascadeStorage storage) {
    const auto& storages = describe(kind).storages;
    return storages.empty() || std::find(storages.begin(), storages.end(), storage) != storages.end();
}

}  // namespace st
