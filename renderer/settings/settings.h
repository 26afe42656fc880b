#pragma once
// The one value everything tunable lives in: the editor edits it, presets serialise it, the
// renderer consumes it and headless replay loads it. No GL, no JSON here: plain data only.
// Every field listed here has a row in field_table.cpp (label, range, unit, help); a field that
// is missing there is a bug (tests/settings checks the table covers the JSON round trip).
#include "shaders/codes.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace st {

// Each enum's values are the codes of shaders/codes.h (the shaders read them as ints), and its
// JSON names sit next to it: EnumNames<E>::names[i] names the enumerator of value i
// (lowercase-kebab; enum_names.h has the helpers). The static_asserts tie the three together.
template <class E>
struct EnumNames;

enum class SplitScheme {
    Uniform = ST_SPLIT_UNIFORM,
    Logarithmic = ST_SPLIT_LOGARITHMIC,
    Practical = ST_SPLIT_PRACTICAL,
    Manual = ST_SPLIT_MANUAL,
};
template <>
struct EnumNames<SplitScheme> {
    static constexpr std::array<std::string_view, ST_SPLIT_COUNT> names{"uniform", "logarithmic", "practical", "manual"};
};

// Cascade: tight light-space AABB of each slice (crop matrix, seeds 000/002).
// Scene: every cascade starts at the camera near plane (seed 004 "fit to scene").
// Sphere: bounding sphere of the slice, size constant under rotation (seed 001).
// Samples: the light-space bounds of the visible samples the cascade holds (Lauritzen et al.
// 2011, "Sample Distribution Shadow Maps"), reduced from the camera's depth buffer.
// Diagonal: a square as wide as the slice's longer diagonal (far face or body), centred on the
// slice's light-space box, its centre floored to whole texels when stabilized (three.js r187,
// examples/jsm/csm/CSM.js _updateShadowBounds and update()).
enum class FitMode {
    Cascade = ST_FIT_CASCADE,
    Scene = ST_FIT_SCENE,
    Sphere = ST_FIT_SPHERE,
    Samples = ST_FIT_SAMPLES,
    Diagonal = ST_FIT_DIAGONAL,
};
template <>
struct EnumNames<FitMode> {
    static constexpr std::array<std::string_view, ST_FIT_COUNT> names{"cascade", "scene", "sphere", "samples", "diagonal"};
};

// Which faces of single-sided materials the shadow pass draws; double-sided ones draw both.
// Back: the faces turned away from the sun, so a closed caster's stored depth is its far side and
// its lit face never compares against itself (acne hidden; three.js's default, WebGLShadowMap.js
// shadowSide; Woo 1992's "second depth" idea in its simplest form).
enum class CasterFaces { Both = ST_FACES_BOTH, Back = ST_FACES_BACK, Front = ST_FACES_FRONT };
template <>
struct EnumNames<CasterFaces> {
    static constexpr std::array<std::string_view, ST_FACES_COUNT> names{"both", "back", "front"};
};

// How a stabilized light box moves onto the texel grid (cascades.stabilize): BoxFloor floors its
// min corner to texels of size / (m - 1) (seed 001); CentreFloor floors its centre to texels of
// size / m (three.js CSM.js update()); CentreRound rounds its centre, which puts the world origin on
// a texel corner (Babylon.js cascadedShadowGenerator.pure.js _computeMatrices).
enum class Snap { BoxFloor = ST_SNAP_BOX_FLOOR, CentreFloor = ST_SNAP_CENTRE_FLOOR, CentreRound = ST_SNAP_CENTRE_ROUND };
template <>
struct EnumNames<Snap> {
    static constexpr std::array<std::string_view, ST_SNAP_COUNT> names{"box-floor", "centre-floor", "centre-round"};
};

// Where the sphere fit centres each slice's sphere: Smallest, the smallest sphere around the slice
// (its centre on the view axis); CornersMean, the mean of the slice's 8 corners with the farthest
// corner on it, a looser sphere (Babylon.js stabilizeCascades, cascadedShadowGenerator.pure.js:473-483;
// Godot's split spheres). Both radii are rounded up to 1/16 m.
enum class SphereCentre { Smallest = ST_SPHERE_SMALLEST, CornersMean = ST_SPHERE_CORNERS_MEAN };
template <>
struct EnumNames<SphereCentre> {
    static constexpr std::array<std::string_view, ST_SPHERE_COUNT> names{"smallest", "corners-mean"};
};

// Where the cascade fit finds each slice's corners: Exact from the camera's planes; Float32Inverse
// as an engine that keeps its matrices in float32 does, unprojecting the NDC cube through the
// float32 inverse of the camera's view-projection (Babylon.js; renderer/csm/float32_corners.h). Far
// corners then move by up to ~1e-4 of their distance: nothing a user sees, but where acne stripes fall.
enum class SliceCorners { Exact = ST_CORNERS_EXACT, Float32Inverse = ST_CORNERS_FLOAT32_INVERSE };
template <>
struct EnumNames<SliceCorners> {
    static constexpr std::array<std::string_view, ST_CORNERS_COUNT> names{"exact", "float32-inverse"};
};

// What bias.constant counts: metres along the light, or the light box's normalised depth (three.js's
// shadowBias on the receiver, Babylon.js's bias on the caster), whose metres grow with each box's depth.
enum class BiasUnit { Metres = ST_BIASUNIT_METRES, Depth = ST_BIASUNIT_DEPTH };
template <>
struct EnumNames<BiasUnit> {
    static constexpr std::array<std::string_view, ST_BIASUNIT_COUNT> names{"metres", "depth"};
};

// What bias.normalOffset counts: the cascade's texels (scales with the map's footprint) or metres
// (three.js's and Babylon's normalBias).
// What bias.normalOffset moves: the receiver's lookup, out along its normal (three.js, seed 004's
// normal offset), or the caster, into its own surface by the offset times the sine of the angle
// between its normal and the sun (Babylon.js shadowMapVertexNormalBias.js): nothing on faces square to
// the sun, the whole offset on faces edge-on to it.
enum class NormalOffsetSide { Receiver = ST_NORMALSIDE_RECEIVER, CasterSin = ST_NORMALSIDE_CASTER_SIN };
template <>
struct EnumNames<NormalOffsetSide> {
    static constexpr std::array<std::string_view, ST_NORMALSIDE_COUNT> names{"receiver", "caster-sin"};
};

enum class OffsetUnit { Texels = ST_OFFSET_TEXELS, Metres = ST_OFFSET_METRES };
template <>
struct EnumNames<OffsetUnit> {
    static constexpr std::array<std::string_view, ST_OFFSET_COUNT> names{"texels", "metres"};
};

// Where the split scheme places the splits: Off = [camera near, far or shadow distance];
// Fit = inside the nearest and farthest view depth the camera actually sees (SDSM, Lauritzen
// et al. 2011), reduced from a depth prepass of the same frame.
enum class DepthBounds { Off = ST_DEPTH_BOUNDS_OFF, Fit = ST_DEPTH_BOUNDS_FIT };
template <>
struct EnumNames<DepthBounds> {
    static constexpr std::array<std::string_view, ST_DEPTH_BOUNDS_COUNT> names{"off", "fit"};
};

// How far the light box reaches toward the light beyond the slice itself.
// Pancake: no extension, casters in front are clamped onto the near plane (depth clamp, seed 001).
enum class ZExtension {
    None = ST_ZEXT_NONE,
    Distance = ST_ZEXT_DISTANCE,
    SceneBounds = ST_ZEXT_SCENE_BOUNDS,
    Pancake = ST_ZEXT_PANCAKE,
};
template <>
struct EnumNames<ZExtension> {
    static constexpr std::array<std::string_view, ST_ZEXT_COUNT> names{"none", "distance", "scene-bounds", "pancake"};
};

// Seed 004: view depth vs first map that contains the point.
enum class Selection { Interval = ST_SELECT_INTERVAL, Map = ST_SELECT_MAP };
template <>
struct EnumNames<Selection> {
    static constexpr std::array<std::string_view, ST_SELECT_COUNT> names{"interval", "map"};
};

// Vsm..Msm filter a map of depth moments instead of comparing depths (renderer/render/moment_maps.h):
// VSM (seed 004, Donnelly & Lauritzen 2006), EVSM with the positive warp or both (Lauritzen &
// McCool 2008), MSM with four moments and the Hamburger reconstruction (Peters & Klein 2015).
enum class FilterKind {
    Hard = ST_FILTER_HARD,
    Pcf2x2 = ST_FILTER_PCF2X2,
    PcfNxN = ST_FILTER_PCF_NXN,
    Vsm = ST_FILTER_VSM,
    Evsm2 = ST_FILTER_EVSM2,
    Evsm4 = ST_FILTER_EVSM4,
    Msm = ST_FILTER_MSM,
    Pcss = ST_FILTER_PCSS,
    Vogel = ST_FILTER_VOGEL,
    Tent = ST_FILTER_TENT,
};
template <>
struct EnumNames<FilterKind> {
    static constexpr std::array<std::string_view, ST_FILTER_COUNT> names{"hard", "pcf2x2", "pcf-nxn", "vsm",
                                                                         "evsm2", "evsm4", "msm", "pcss",
                                                                         "pcf-vogel", "pcf-tent"};
};
constexpr bool isMomentFilter(FilterKind k) { return k >= FilterKind::Vsm && k <= FilterKind::Msm; }

// Weights of the NxN PCF taps: equal, or a Gaussian (seed 004, CascadedShadowMaps11).
enum class FilterWeights { Box = ST_WEIGHTS_BOX, Gaussian = ST_WEIGHTS_GAUSSIAN };
template <>
struct EnumNames<FilterWeights> {
    static constexpr std::array<std::string_view, ST_WEIGHTS_COUNT> names{"box", "gaussian"};
};

// Off: the main pass filters the maps itself. Blur: seed 001's screen-space soft shadows, the
// filter's factor per pixel blurred in screen space, depth-aware (renderer/render/screen_shadow.h).
enum class ScreenSpace { Off = ST_SCREEN_OFF, Blur = ST_SCREEN_BLUR };
template <>
struct EnumNames<ScreenSpace> {
    static constexpr std::array<std::string_view, ST_SCREEN_COUNT> names{"off", "blur"};
};

// Off: the map's factor alone. March: contact shadows, a short ray march toward the sun through
// the camera's depth buffer near each receiver, its factor combined with the map's by min() (Godot
// PR #118045): contacts a large bias or a coarse map detaches get their shadow back.
enum class ContactShadows { Off = ST_CONTACT_OFF, March = ST_CONTACT_MARCH };
template <>
struct EnumNames<ContactShadows> {
    static constexpr std::array<std::string_view, ST_CONTACT_COUNT> names{"off", "march"};
};

// Where the cascades' depth maps live (renderer/csm/storage_layout.h). Array: one layer per
// cascade of a D32F array, one size for all. Atlas: one texture, a viewport per tile (seed 003).
// Textures: one texture per cascade (seed 002). Atlas and textures allow a size per cascade.
enum class CascadeStorage { Array = ST_STORAGE_ARRAY, Atlas = ST_STORAGE_ATLAS, Textures = ST_STORAGE_TEXTURES };
template <>
struct EnumNames<CascadeStorage> {
    static constexpr std::array<std::string_view, ST_STORAGE_COUNT> names{"array", "atlas", "textures"};
};

// TexelDensity: screen pixels per shadow texel as a heat map (blue < 1/4 wasted, green 1 ideal,
// red > 1 perspective aliasing; docs/architecture.md#texel-density).
// Side: the frame from an outside orbit camera with the main frustum, its split planes and each
// cascade's light box as wireframes.
enum class View {
    Shaded = ST_VIEW_SHADED,
    Cascades = ST_VIEW_CASCADES,
    Shadow = ST_VIEW_SHADOW,
    TexelDensity = ST_VIEW_TEXEL_DENSITY,
    Side = ST_VIEW_SIDE,
    TexelGrid = ST_VIEW_TEXEL_GRID,
};
template <>
struct EnumNames<View> {
    static constexpr std::array<std::string_view, ST_VIEW_COUNT> names{"shaded", "cascades", "shadow", "texel-density", "side",
                                                                      "texel-grid"};
};

// The codes of an enum run 0..COUNT-1 with no gap, so a value indexes its name table and a code
// read from a file is valid exactly when it is below the table's size.
static_assert(int(SplitScheme::Manual) == ST_SPLIT_COUNT - 1 && int(SplitScheme::Uniform) == 0);
static_assert(int(FitMode::Diagonal) == ST_FIT_COUNT - 1 && int(FitMode::Cascade) == 0);
static_assert(int(CasterFaces::Front) == ST_FACES_COUNT - 1 && int(CasterFaces::Both) == 0);
static_assert(int(Snap::CentreRound) == ST_SNAP_COUNT - 1 && int(Snap::BoxFloor) == 0);
static_assert(int(SliceCorners::Float32Inverse) == ST_CORNERS_COUNT - 1 && int(SliceCorners::Exact) == 0);
static_assert(int(NormalOffsetSide::CasterSin) == ST_NORMALSIDE_COUNT - 1 && int(NormalOffsetSide::Receiver) == 0);
static_assert(int(SphereCentre::CornersMean) == ST_SPHERE_COUNT - 1 && int(SphereCentre::Smallest) == 0);
static_assert(int(BiasUnit::Depth) == ST_BIASUNIT_COUNT - 1 && int(BiasUnit::Metres) == 0);
static_assert(int(OffsetUnit::Metres) == ST_OFFSET_COUNT - 1 && int(OffsetUnit::Texels) == 0);
static_assert(int(DepthBounds::Fit) == ST_DEPTH_BOUNDS_COUNT - 1 && int(DepthBounds::Off) == 0);
static_assert(int(ZExtension::Pancake) == ST_ZEXT_COUNT - 1 && int(ZExtension::None) == 0);
static_assert(int(Selection::Map) == ST_SELECT_COUNT - 1 && int(Selection::Interval) == 0);
static_assert(int(FilterKind::Tent) == ST_FILTER_COUNT - 1 && int(FilterKind::Hard) == 0);
static_assert(int(FilterWeights::Gaussian) == ST_WEIGHTS_COUNT - 1 && int(FilterWeights::Box) == 0);
static_assert(int(ScreenSpace::Blur) == ST_SCREEN_COUNT - 1 && int(ScreenSpace::Off) == 0);
static_assert(int(ContactShadows::March) == ST_CONTACT_COUNT - 1 && int(ContactShadows::Off) == 0);
static_assert(int(CascadeStorage::Textures) == ST_STORAGE_COUNT - 1 && int(CascadeStorage::Array) == 0);
static_assert(int(View::TexelGrid) == ST_VIEW_COUNT - 1 && int(View::Shaded) == 0);

// The code the shaders read for an enumerator (shaders/codes.h): its value, never remapped.
template <class E>
constexpr int shaderCode(E value) {
    return static_cast<int>(value);
}

struct CameraSettings {
    glm::vec3 position{0.0f, 1.7f, 10.0f};  // ws, metres
    glm::vec3 target{0.0f, 1.0f, 0.0f};     // ws, metres
    float fovY = 60.0f;                      // degrees, vertical
    float nearPlane = 0.1f;                  // metres
    float farPlane = 400.0f;                 // metres
    bool operator==(const CameraSettings&) const = default;
};

struct LightSettings {
    float azimuth = 35.0f;    // degrees, from +X toward +Z, direction the sun is in
    float elevation = 40.0f;  // degrees above the horizon; 90 = overhead (light travels straight down)
    float intensity = 1.0f;   // multiplier of the direct (Lambert) term
    float ambient = 0.15f;    // constant term, never shadowed
    float angularDiameter = 0.53f;  // degrees, the sun's disc (0.53 = the real sun); 0 = a point sun
    bool operator==(const LightSettings&) const = default;
};

// The most cascades a preset may ask for; the shaders' arrays hold this many.
inline constexpr int kMaxCascades = ST_MAX_CASCADES;

struct CascadeSettings {
    int count = 4;                         // 1..kMaxCascades
    SplitScheme scheme = SplitScheme::Practical;
    float lambda = 0.5f;                   // seed 000: 1 = fully logarithmic, 0 = uniform
    std::vector<float> manualSplits;       // view-depth ends of cascades 0..count-2, metres, increasing
    float shadowDistance = 0.0f;           // metres; 0 = camera far plane
    DepthBounds depthBounds = DepthBounds::Off;
    int mapSize = 1024;                    // texels per side, power of two 256..8192
    CascadeStorage storage = CascadeStorage::Array;
    std::vector<int> mapSizes;             // per cascade (atlas, textures); empty = mapSize for all
    int atlasPadding = 8;                  // texels of lit border between atlas tiles
    FitMode fit = FitMode::Cascade;
    bool stabilize = false;                // snap the light box to whole texels (seed 001)
    Snap snap = Snap::BoxFloor;            // how, when stabilize is on
    SliceCorners sliceCorners = SliceCorners::Exact;  // where the fit finds each slice's corners
    SphereCentre sphereCentre = SphereCentre::Smallest;  // where the sphere fit centres its sphere
    ZExtension zExtension = ZExtension::SceneBounds;
    float zExtensionDistance = 100.0f;     // metres, for ZExtension::Distance
    float lightDepth = 0.0f;               // metres from the box's near plane to its far one; 0 = to the slice's far side
    CasterFaces casterFaces = CasterFaces::Both;
    bool pancakeToCasters = false;         // pancake: the box's depth tightened to the casters' bounds (Babylon.js)
    Selection selection = Selection::Interval;
    float blendBand = 0.0f;                // fraction of a cascade's depth range blended into the next, 0..0.5
    bool casterCulling = true;             // cull casters whose shadow cannot reach the slice (Bittner 2011)
    std::vector<float> updateInterval;     // frames between redraws of cascade i (whole numbers >= 1); missing = 1
    float fadeBand = 0.0f;                 // fraction of the last cascade's range faded to lit at its far end, 0..1
    // Light-space math relative to the camera (the texel grid's phase taken in double), so snapping
    // stays exact when Settings::origin puts the scene far from the world origin.
    bool cameraRelative = false;
    float fitFovY = 0.0f;                  // degrees: fit the boxes for at least this vertical FOV; 0 = the camera's
    bool matricesOneFrameLate = false;     // debug: sample the maps through the previous frame's matrices
    bool operator==(const CascadeSettings&) const = default;
};

struct FilterSettings {
    FilterKind kind = FilterKind::Pcf2x2;
    int size = 3;  // taps per side for PcfNxN, odd, 3..9
    FilterWeights weights = FilterWeights::Box;  // of the PcfNxN taps
    bool padding = false;  // grow each light box so the kernel never reads past the map (seed 004)
    // Moment filters (Vsm..Msm):
    int blurRadius = 2;           // texels each side of the separable Gaussian blur, 0 = none
    bool mipmaps = false;         // trilinear reads of a mipmapped moment array
    bool moments16 = false;       // 16-bit storage (EVSM exponents clamp at 5.54, MSM quantised)
    float minVariance = 1e-5f;    // VSM/EVSM variance floor, squared shadow-texture depth units
    float bleedExponent = 1.0f;   // lit share raised to this power against light bleeding; 1 = off
    float bleedLow = 0.0f;        // lit share remapped from [bleedLow, bleedHigh] to [0, 1] (three.js: 0.3, 0.95)
    float bleedHigh = 1.0f;
    float evsmPositive = 40.0f;   // EVSM exponents, clamped at 42 (32-bit) or 5.54 (16-bit)
    float evsmNegative = 5.0f;
    float momentBias = 3e-5f;     // MSM: share the moments are pulled toward 0.5
    // PCSS (filter.size taps per side spread over the estimated penumbra):
    int blockerTaps = 5;          // taps per side of the blocker search, odd
    float pcssMaxRadius = 32.0f;  // texels: cap of the search and kernel radius (see shadow_sampling.glsl)
    // Vogel-disc PCF (three.js r187 shadowmap_pars_fragment.glsl.js): vogelTaps bilinear compares
    // within `radius` texels, the disc rotated per pixel by interleaved gradient noise.
    int vogelTaps = 5;
    float radius = 1.0f;          // texels; 0 = every tap at the pixel's own point (the 2x2 compare)
    // Seed 001's screen-space path (any kind above makes the mask it blurs):
    ScreenSpace screenSpace = ScreenSpace::Off;
    int screenDownsample = 2;     // the mask is blurred at 1/N of the output size: 1, 2 (seed 001) or 4
    int screenBlurRadius = 4;     // downsampled pixels each side of the separable Gaussian, 0 = none
    float screenDepthSigma = 0.1f;// depth-aware weight: sigma as a fraction of the view depth; 0 = off
    // Contact shadows (drawn on the screen-space path's mask and depth):
    ContactShadows contact = ContactShadows::Off;
    float contactLength = 0.5f;      // metres marched toward the sun from each receiver
    int contactSteps = 12;           // depth samples along the march
    float contactThickness = 0.3f;   // metres behind the depth buffer that still occlude
    bool operator==(const FilterSettings&) const = default;
};

struct BiasSettings {
    float constant = 0.02f;     // toward the light, in constantUnit (negative: away, as three.js's positive shadowBias)
    BiasUnit constantUnit = BiasUnit::Metres;
    float slope = 1.0f;         // texel world sizes per unit of tan(angle to light)
    float normalOffset = 0.0f;  // receiver moved along its normal, in normalOffsetUnit
    OffsetUnit normalOffsetUnit = OffsetUnit::Texels;
    NormalOffsetSide normalOffsetSide = NormalOffsetSide::Receiver;  // what the offset moves
    bool receiverPlane = false; // derivative-based receiver-plane depth bias (seed 004)
    // Per cascade factors of constant, slope and normal offset (cascadeBias below): empty = 1 for every
    // cascade, else one per cascade. Factors, not values, so the global knobs stay the artist's one
    // control and a tuner searches a unitless number near 1 per cascade.
    std::vector<float> constantScale;
    std::vector<float> slopeScale;
    std::vector<float> normalOffsetScale;
    bool operator==(const BiasSettings&) const = default;
};

// The bias one cascade applies: the global constant, slope and normal offset times that cascade's
// factor (1 where a list is empty or shorter), each in its own unit. The shader
// (CascadeData::biasScale) and the exporters read it here; cascadeBiasMetres turns it into metres.
struct CascadeBias {
    float constant = 0.0f;      // bias.constantUnit: metres, or the light box's normalised depth
    float slope = 0.0f;         // texel world sizes per unit tan(angle to the sun)
    float normalOffset = 0.0f;  // bias.normalOffsetUnit: texel world sizes, or metres
};

inline float cascadeFactor(const std::vector<float>& factors, int cascade) {
    const auto i = static_cast<std::size_t>(cascade);
    return i < factors.size() ? factors[i] : 1.0f;
}

inline CascadeBias cascadeBias(const BiasSettings& b, int cascade) {
    return {b.constant * cascadeFactor(b.constantScale, cascade), b.slope * cascadeFactor(b.slopeScale, cascade),
            b.normalOffset * cascadeFactor(b.normalOffsetScale, cascade)};
}

// What bias.normalOffsetSide moves by the normal offset: the receivers (shadow_sampling.glsl
// shadowCoord), or the casters, by the offset x sin(N, L) (shadow_depth.vert; metres only).
inline float receiverNormalOffset(const BiasSettings& b) {
    return b.normalOffsetSide == NormalOffsetSide::Receiver ? b.normalOffset : 0.0f;
}
inline float casterNormalOffset(const BiasSettings& b) {
    return b.normalOffsetSide == NormalOffsetSide::CasterSin ? b.normalOffset : 0.0f;
}

// Cascade i's bias in metres, as the shaders apply it (shadow_sampling.glsl biasedDepth and
// shadowCoord, shadow_depth.vert), given that cascade's texel and light-box depth in metres.
struct CascadeBiasMetres {
    float constant = 0.0f;        // along the light
    float slopePerTan = 0.0f;     // along the light, per unit tan(angle to the sun)
    float receiverOffset = 0.0f;  // receivers moved out along their normal
    float casterOffset = 0.0f;    // casters moved in along theirs, before the x sin(N, L)
};
inline CascadeBiasMetres cascadeBiasMetres(const BiasSettings& b, int cascade, float texelWorld, float depthRange) {
    const CascadeBias c = cascadeBias(b, cascade);
    const float offsetUnit = b.normalOffsetUnit == OffsetUnit::Metres ? 1.0f : texelWorld;
    const float offset = c.normalOffset * offsetUnit;
    return {c.constant * (b.constantUnit == BiasUnit::Depth ? depthRange : 1.0f), c.slope * texelWorld,
            b.normalOffsetSide == NormalOffsetSide::Receiver ? offset : 0.0f,
            b.normalOffsetSide == NormalOffsetSide::CasterSin ? offset : 0.0f};
}

// True when some cascade's factor differs from 1: the preset biases its cascades differently.
inline bool hasCascadeBias(const BiasSettings& b) {
    for (const std::vector<float>* list : {&b.constantScale, &b.slopeScale, &b.normalOffsetScale})
        for (float f : *list)
            if (f != 1.0f) return true;
    return false;
}

struct OutputSettings {
    int width = 640;
    int height = 360;
    View view = View::Shaded;
    int texelBlock = 8;      // texel-grid view: texels per side of a checker block (seed 003)
    bool sideTexels = false; // side view: the maps' texels back-projected into the world (seed 003)
    bool operator==(const OutputSettings&) const = default;
};

// One pose of a camera path. Its fields follow the rules of camera.position/target/fovY.
struct CameraKeyframe {
    glm::vec3 position{0.0f, 1.7f, 10.0f};  // ws, metres
    glm::vec3 target{0.0f, 1.0f, 0.0f};     // ws, metres
    float fovY = 60.0f;                      // degrees, vertical
    bool operator==(const CameraKeyframe&) const = default;
};

// A camera path for the flicker measurement (docs/architecture.md#flicker): the *cascade
// camera* moves through the keyframes (linearly, evenly over `frames` frames) and drives the
// cascades, while the preset's `camera` stays put as the observer that sees the shadows.
struct PathSettings {
    int frames = 0;                        // 0 = no path
    std::vector<CameraKeyframe> keyframes;  // at least one when frames > 0
    bool operator==(const PathSettings&) const = default;
};

// How `measure` scores a frame (docs/architecture.md#the-suns-disc, #artifact-classes).
struct MeasureSettings {
    int sunRays = 16;            // rays over the sun's disc per pixel for the soft truth
    float artifactTexels = 2.0f; // k: light bleeding is more, peter-panning within, k texels of an edge / contact
    bool operator==(const MeasureSettings&) const = default;
};

struct Settings {
    std::string scene = "builtin:yard";  // "builtin:NAME" or a glTF path relative to the preset
    std::string notes;                   // free text: what of the source system is not reproduced
    bool ground = false;                 // a ground quad under a glTF scene that has none (SceneOptions)
    // Where the scene sits in the engine's world, metres. The light matrices are built from world
    // positions (scene + origin) as an engine far from its origin would, then expressed back in scene
    // coordinates: camera, path and geometry stay relative to the scene (renderer/csm/light_fit.h).
    glm::vec3 origin{0.0f};
    CameraSettings camera;
    LightSettings light;
    CascadeSettings cascades;
    FilterSettings filter;
    BiasSettings bias;
    OutputSettings output;
    PathSettings path;
    MeasureSettings measure;
    bool operator==(const Settings&) const = default;
};

}  // namespace st
