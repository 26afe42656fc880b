#include "renderer/settings/field_table.h"

#include "renderer/settings/enum_names.h"

#include <algorithm>
#include <type_traits>
#include <utility>

namespace st {

std::string_view unitIn(const FieldInfo& field, const Settings& s) {
    if (field.path == "bias.normalOffset") return s.bias.normalOffsetUnit == OffsetUnit::Metres ? "m" : "texels";
    if (field.path == "bias.constant") return s.bias.constantUnit == BiasUnit::Depth ? "of the light box's depth" : "m";
    return field.unit;
}

namespace {

template <class T>
FieldValue toValue(const T& value) {
    if constexpr (std::is_enum_v<T>) {
        return FieldValue(std::in_place_type<int>, static_cast<int>(value));
    } else {
        return FieldValue(std::in_place_type<T>, value);
    }
}

template <class T>
void fromValue(const FieldValue& value, T& out) {
    if constexpr (std::is_enum_v<T>) {
        out = static_cast<T>(std::get<int>(value));
    } else {
        out = std::get<T>(value);
    }
}

// Getter and setter of one Settings member, as the last two designated initialisers of a row.
#define ST_FIELD_ACCESS(member)                                        \
    .get = [](const Settings& s) { return toValue(s.member); },        \
    .set = [](Settings& s, const FieldValue& v) { fromValue(v, s.member); }

using K = FieldKind;
using C = ChangeClass;

std::vector<FieldInfo> sceneAndCameraRows() {
    return {
        {.path = "scene", .label = "Scene",
         .help = "Which geometry to shadow: \"builtin:NAME\" or a glTF path relative to the preset file.",
         .kind = K::String, .nonEmpty = true, .change = C::Scene, ST_FIELD_ACCESS(scene)},
        {.path = "notes", .label = "Notes",
         .help = "Free text recording what of the reproduced system this preset does not match.",
         .kind = K::String, .change = C::None, ST_FIELD_ACCESS(notes)},
        {.path = "ground", .label = "Ground plane",
         .help = "Adds a ground, 4x the scene's width, under its lowest point: for glTF scenes whose shadows have nowhere to fall.",
         .kind = K::Bool, .change = C::Scene, ST_FIELD_ACCESS(ground)},
        {.path = "origin", .label = "World origin offset",
         .help = "Where the scene sits in the engine's world: light matrices built far out lose float precision unless camera-relative.",
         .unit = "m", .kind = K::Vec3, .min = -1e7, .max = 1e7, .step = 1, ST_FIELD_ACCESS(origin)},
        {.path = "camera.position", .label = "Camera position",
         .help = "Where the viewer stands; moving it shows how the cascades follow the camera.",
         .unit = "m", .kind = K::Vec3, .min = -1e6, .max = 1e6, .step = 0.1, ST_FIELD_ACCESS(camera.position)},
        {.path = "camera.target", .label = "Camera target",
         .help = "The point the camera looks at, which sets the view direction the cascades are sliced along.",
         .unit = "m", .kind = K::Vec3, .min = -1e6, .max = 1e6, .step = 0.1, ST_FIELD_ACCESS(camera.target)},
        {.path = "camera.fovY", .label = "Vertical FOV",
         .help = "A wider field of view widens every cascade slice and so lowers shadow resolution per pixel.",
         .unit = "deg", .kind = K::Float, .min = 1, .max = 179, .step = 0.5, ST_FIELD_ACCESS(camera.fovY)},
        {.path = "camera.nearPlane", .label = "Near plane",
         .help = "Logarithmic splits crowd toward the near plane, so pushing it out frees resolution for far cascades.",
         .unit = "m", .kind = K::Float, .min = 1e-4, .max = 1e4, .step = 0.01, ST_FIELD_ACCESS(camera.nearPlane)},
        {.path = "camera.farPlane", .label = "Far plane",
         .help = "The end of the view range; the last cascade ends here unless a shadow distance is set.",
         .unit = "m", .kind = K::Float, .min = 1e-4, .max = 1e6, .step = 1, ST_FIELD_ACCESS(camera.farPlane)},
    };
}

std::vector<FieldInfo> lightRows() {
    return {
        {.path = "light.azimuth", .label = "Sun azimuth",
         .help = "Turns the sun about the vertical axis (from +X toward +Z) to test every orientation to the view.",
         .unit = "deg", .kind = K::Float, .min = -360, .max = 360, .step = 1, ST_FIELD_ACCESS(light.azimuth)},
        {.path = "light.elevation", .label = "Sun elevation",
         .help = "Low suns stretch shadows and expose acne and peter-panning; 90 is straight overhead.",
         .unit = "deg", .kind = K::Float, .min = -90, .max = 90, .step = 1, ST_FIELD_ACCESS(light.elevation)},
        {.path = "light.intensity", .label = "Sun intensity",
         .help = "Scales the direct light so shadow contrast can be judged against the ambient term.",
         .kind = K::Float, .min = 0, .max = 10, .step = 0.01, .shader = "intensity", ST_FIELD_ACCESS(light.intensity)},
        {.path = "light.ambient", .label = "Ambient",
         .help = "Constant, never shadowed light that keeps shadowed areas readable.",
         .kind = K::Float, .min = 0, .max = 1, .step = 0.01, .shader = "ambient", ST_FIELD_ACCESS(light.ambient)},
        {.path = "light.angularDiameter", .label = "Sun angular diameter",
         .help = "The sun's disc as seen from the scene: 0.53 is the real sun; it sets the width of true penumbrae (0 = a point light).",
         .unit = "deg", .kind = K::Float, .min = 0, .max = 10, .step = 0.01, ST_FIELD_ACCESS(light.angularDiameter)},
    };
}

std::vector<FieldInfo> cascadeSplitRows() {
    return {
        {.path = "cascades.count", .label = "Cascades",
         .help = "More cascades spread shadow map resolution more evenly over depth, at one shadow pass each.",
         .kind = K::Int, .min = 1, .max = kMaxCascades, .step = 1, .change = C::Reallocate, .shader = "cascadeCount", ST_FIELD_ACCESS(cascades.count)},
        {.path = "cascades.scheme", .label = "Split scheme",
         .help = "How the view depth range is divided: uniform, logarithmic, their lambda blend, or manual depths.",
         .kind = K::Enum, .enumNames = enumNames<SplitScheme>(), ST_FIELD_ACCESS(cascades.scheme)},
        {.path = "cascades.lambda", .label = "Lambda",
         .help = "Practical-split blend: 1 is fully logarithmic, 0 uniform; higher gives near cascades more resolution.",
         .kind = K::Float, .min = 0, .max = 1, .step = 0.01, ST_FIELD_ACCESS(cascades.lambda)},
        {.path = "cascades.manualSplits", .label = "Manual splits",
         .help = "View-depth ends of cascades 0..count-2 for the manual scheme, to copy a system's exact splits.",
         .unit = "m", .kind = K::FloatList, .min = 0, .max = 1e6, .step = 0.1,
         ST_FIELD_ACCESS(cascades.manualSplits)},
        {.path = "cascades.shadowDistance", .label = "Shadow distance",
         .help = "Ends the last cascade before the far plane so no resolution goes to distant shadows; 0 = far plane.",
         .unit = "m", .kind = K::Float, .min = 0, .max = 1e6, .step = 1, ST_FIELD_ACCESS(cascades.shadowDistance)},
        {.path = "cascades.depthBounds", .label = "Depth bounds",
         .help = "fit: splits placed inside the nearest and farthest depth the camera sees (a depth prepass), not up to the far plane.",
         .kind = K::Enum, .enumNames = enumNames<DepthBounds>(), ST_FIELD_ACCESS(cascades.depthBounds)},
        {.path = "cascades.mapSize", .label = "Map size",
         .help = "Texels per side of each cascade's map; doubling halves the texel footprint at 4x the memory.",
         .unit = "texels", .kind = K::Int, .min = 256, .max = 8192, .step = 1, .powerOfTwo = true,
         .change = C::Reallocate, ST_FIELD_ACCESS(cascades.mapSize)},
        {.path = "cascades.storage", .label = "Storage",
         .help = "Where the maps live: layers of one array, tiles of one atlas (seed 003), or a texture per cascade (seed 002).",
         .kind = K::Enum, .enumNames = enumNames<CascadeStorage>(), .change = C::Reallocate, .shader = "storage",
         ST_FIELD_ACCESS(cascades.storage)},
        {.path = "cascades.mapSizes", .label = "Map sizes",
         .help = "Texels per side of each cascade (atlas, textures storage), so far cascades spend less; empty = map size for all.",
         .unit = "texels", .kind = K::IntList, .min = 256, .max = 8192, .step = 1, .powerOfTwo = true,
         .change = C::Reallocate, ST_FIELD_ACCESS(cascades.mapSizes)},
        {.path = "cascades.atlasPadding", .label = "Atlas padding",
         .help = "Lit texels between atlas tiles, so taps past a tile's edge read lit, not its edge texels (0: none, as seed 003).",
         .unit = "texels", .kind = K::Int, .min = 0, .max = 64, .step = 1, .change = C::Reallocate,
         ST_FIELD_ACCESS(cascades.atlasPadding)},
    };
}

std::vector<FieldInfo> cascadeFitRows() {
    return {
        {.path = "cascades.fit", .label = "Fit",
         .help = "Light box fit: tight to its slice, from the near plane, a rotation-stable sphere, or the visible samples it holds.",
         .kind = K::Enum, .enumNames = enumNames<FitMode>(), ST_FIELD_ACCESS(cascades.fit)},
        {.path = "cascades.stabilize", .label = "Stabilize",
         .help = "Snaps each light box to whole texels so shadow edges do not shimmer as the camera moves.",
         .kind = K::Bool, ST_FIELD_ACCESS(cascades.stabilize)},
        {.path = "cascades.snap", .label = "Snap",
         .help = "How a stabilized box meets the texel grid: min corner floored, centre floored (three.js) or rounded (Babylon).",
         .kind = K::Enum, .enumNames = enumNames<Snap>(), ST_FIELD_ACCESS(cascades.snap)},
        {.path = "cascades.zExtension", .label = "Z extension",
         .help = "How far each light box reaches toward the light, so casters outside the slice still cast into it.",
         .kind = K::Enum, .enumNames = enumNames<ZExtension>(), ST_FIELD_ACCESS(cascades.zExtension)},
        {.path = "cascades.zExtensionDistance", .label = "Z extension distance",
         .help = "Reach toward the light for the distance extension: too short clips casters, too long wastes depth.",
         .unit = "m", .kind = K::Float, .min = 0, .max = 1e5, .step = 1, ST_FIELD_ACCESS(cascades.zExtensionDistance)},
        {.path = "cascades.lightDepth", .label = "Light box depth",
         .help = "Metres from each light box's near plane to its far one (three.js: lightFar - lightNear); 0 = to the slice's far side.",
         .unit = "m", .kind = K::Float, .min = 0, .max = 1e6, .step = 1, ST_FIELD_ACCESS(cascades.lightDepth)},
        {.path = "cascades.sliceCorners", .label = "Slice corners",
         .help = "Slice corners from the camera's planes, or through a float32 inverse of its matrices as Babylon.js finds them.",
         .kind = K::Enum, .enumNames = enumNames<SliceCorners>(), ST_FIELD_ACCESS(cascades.sliceCorners)},
        {.path = "cascades.sphereCentre", .label = "Sphere centre",
         .help = "Sphere fit: the smallest sphere around each slice, or one around its corners' mean (Babylon.js, Godot).",
         .kind = K::Enum, .enumNames = enumNames<SphereCentre>(), ST_FIELD_ACCESS(cascades.sphereCentre)},
        {.path = "cascades.pancakeToCasters", .label = "Pancake to casters",
         .help = "Pancake: each box's depth shrunk to the part of the slice the casters' bounds span (Babylon.js), at least 1 m.",
         .kind = K::Bool, ST_FIELD_ACCESS(cascades.pancakeToCasters)},
        {.path = "cascades.casterFaces", .label = "Caster faces",
         .help = "Faces of single-sided materials drawn into the maps: back (three.js) hides acne on closed casters.",
         .kind = K::Enum, .enumNames = enumNames<CasterFaces>(), ST_FIELD_ACCESS(cascades.casterFaces)},
        {.path = "cascades.selection", .label = "Selection",
         .help = "How a pixel picks its cascade: by view-depth interval, or the first map whose box contains it.",
         .kind = K::Enum, .enumNames = enumNames<Selection>(), .shader = "selection", ST_FIELD_ACCESS(cascades.selection)},
        {.path = "cascades.blendBand", .label = "Blend band",
         .help = "Fraction of each cascade's depth range cross-faded into the next, to hide the seam between them.",
         .kind = K::Float, .min = 0, .max = 0.5, .step = 0.01, .shader = "blendBand", ST_FIELD_ACCESS(cascades.blendBand)},
        {.path = "cascades.casterCulling", .label = "Caster culling",
         .help = "Skips casters whose shadow cannot reach what the camera sees in a cascade; the image stays the same.",
         .kind = K::Bool, ST_FIELD_ACCESS(cascades.casterCulling)},
        {.path = "cascades.updateInterval", .label = "Update interval",
         .help = "Frames between redraws of each cascade (e.g. 1, 1, 2, 4): far maps redrawn less often lag the camera.",
         .unit = "frames", .kind = K::FloatList, .min = 1, .max = 64, .step = 1,
         ST_FIELD_ACCESS(cascades.updateInterval)},
        {.path = "cascades.fadeBand", .label = "Fade band",
         .help = "Fraction of the last cascade's depth range faded to lit at its far end, so shadows end softly, not at a line.",
         .kind = K::Float, .min = 0, .max = 1, .step = 0.01, .shader = "fadeBand", ST_FIELD_ACCESS(cascades.fadeBand)},
        {.path = "cascades.cameraRelative", .label = "Camera-relative light space",
         .help = "Builds the light boxes around the camera, not the world origin, so texel snapping stays exact far from the origin.",
         .kind = K::Bool, ST_FIELD_ACCESS(cascades.cameraRelative)},
        {.path = "cascades.fitFovY", .label = "Fit FOV",
         .help = "Fits the light boxes for at least this vertical FOV, so a zoom below it keeps their size (no shimmer); 0 = the camera's.",
         .unit = "deg", .kind = K::Float, .min = 0, .max = 179, .step = 0.5, ST_FIELD_ACCESS(cascades.fitFovY)},
        {.path = "cascades.matricesOneFrameLate", .label = "Matrices one frame late",
         .help = "Debug: samples the maps through the previous frame's light matrices (three.js #30053), to see that bug's flicker.",
         .kind = K::Bool, .debug = true, ST_FIELD_ACCESS(cascades.matricesOneFrameLate)},
    };
}

std::vector<FieldInfo> filterAndBiasRows() {
    return {
        {.path = "filter.kind", .label = "Filter",
         .help = "Shadow edge filtering: one tap, hardware 2x2, NxN taps, PCSS, or a filtered map of depth moments (VSM, EVSM, MSM).",
         .kind = K::Enum, .enumNames = enumNames<FilterKind>(), .shader = "filterKind", ST_FIELD_ACCESS(filter.kind)},
        {.path = "filter.size", .label = "Filter size",
         .help = "Taps per side of the NxN filter; larger softens edges and hides aliasing at quadratic cost.",
         .unit = "taps", .kind = K::Int, .min = 3, .max = 9, .step = 2, .odd = true, .shader = "filterSize", ST_FIELD_ACCESS(filter.size)},
        {.path = "filter.weights", .label = "Filter weights",
         .help = "Weights of the NxN taps: equal (box) or Gaussian, which softens the edge with fewer visible steps.",
         .kind = K::Enum, .enumNames = enumNames<FilterWeights>(), .shader = "filterWeights", ST_FIELD_ACCESS(filter.weights)},
        {.path = "filter.padding", .label = "PCF padding",
         .help = "Grows each light box by the kernel's radius so PCF taps at a cascade's rim still read that cascade's map.",
         .kind = K::Bool, ST_FIELD_ACCESS(filter.padding)},
        {.path = "filter.blurRadius", .label = "Moment blur radius",
         .help = "Texels each side of the moment map's separable Gaussian blur: wider softens penumbrae at more cost; 0 = no blur.",
         .unit = "texels", .kind = K::Int, .min = 0, .max = 16, .step = 1, .shader = "blurRadius", ST_FIELD_ACCESS(filter.blurRadius)},
        {.path = "filter.mipmaps", .label = "Moment mipmaps",
         .help = "Mipmaps the moment map so distant receivers read it trilinearly instead of aliasing.",
         .kind = K::Bool, ST_FIELD_ACCESS(filter.mipmaps)},
        {.path = "filter.moments16", .label = "16-bit moments",
         .help = "Halves the moment map's memory: EVSM exponents clamp at 5.54 and MSM uses Peters & Klein's optimised quantisation.",
         .kind = K::Bool, .shader = "moments16", ST_FIELD_ACCESS(filter.moments16)},
        {.path = "filter.minVariance", .label = "Minimum variance",
         .help = "Variance floor of VSM/EVSM in squared depth units: raising it removes acne on slopes but lightens contact shadows.",
         .kind = K::Float, .min = 0, .max = 0.01, .step = 1e-6, .shader = "minVariance", ST_FIELD_ACCESS(filter.minVariance)},
        {.path = "filter.bleedExponent", .label = "Bleed reduction",
         .help = "Raises a moment filter's lit share to this power (seed 004) to darken light bleeding where shadows overlap; 1 = off.",
         .kind = K::Float, .min = 1, .max = 64, .step = 0.1, .shader = "bleedExponent", ST_FIELD_ACCESS(filter.bleedExponent)},
        {.path = "filter.bleedLow", .label = "Bleed cut",
         .help = "A moment filter's lit share below this reads fully shadowed, the rest stretched to 1: less bleeding.",
         .kind = K::Float, .min = 0, .max = 0.99, .step = 0.01, .shader = "bleedLow", ST_FIELD_ACCESS(filter.bleedLow)},
        {.path = "filter.bleedHigh", .label = "Bleed top",
         .help = "A moment filter's lit share above this reads fully lit (three.js: 0.95); 1 = no change at the top.",
         .kind = K::Float, .min = 0.01, .max = 1, .step = 0.01, .shader = "bleedHigh", ST_FIELD_ACCESS(filter.bleedHigh)},
        {.path = "filter.evsmPositive", .label = "EVSM positive exponent",
         .help = "Steepness of EVSM's positive warp: larger bleeds less; clamped at 42 for 32-bit and 5.54 for 16-bit moments.",
         .kind = K::Float, .min = 0.01, .max = 100, .step = 0.1, ST_FIELD_ACCESS(filter.evsmPositive)},
        {.path = "filter.evsmNegative", .label = "EVSM negative exponent",
         .help = "Steepness of EVSM's negative warp (evsm4 only), clamped like the positive one.",
         .kind = K::Float, .min = 0.01, .max = 100, .step = 0.1, ST_FIELD_ACCESS(filter.evsmNegative)},
        {.path = "filter.momentBias", .label = "MSM moment bias",
         .help = "Pulls MSM's moments toward a flat distribution so rounding cannot make them invalid; larger bleeds more.",
         .kind = K::Float, .min = 0, .max = 0.1, .step = 1e-6, .shader = "momentBias", ST_FIELD_ACCESS(filter.momentBias)},
        {.path = "filter.blockerTaps", .label = "PCSS blocker taps",
         .help = "Taps per side of PCSS's blocker search; more find thin casters at a quadratic cost.",
         .unit = "taps", .kind = K::Int, .min = 3, .max = 9, .step = 2, .odd = true, .shader = "blockerTaps", ST_FIELD_ACCESS(filter.blockerTaps)},
        {.path = "filter.pcssMaxRadius", .label = "PCSS max radius",
         .help = "Cap of PCSS's search and kernel radius in texels: bounds the cost where the penumbra from the sun's disc would be wider.",
         .unit = "texels", .kind = K::Float, .min = 1, .max = 32, .step = 0.5, .shader = "pcssMaxRadius", ST_FIELD_ACCESS(filter.pcssMaxRadius)},
        {.path = "filter.vogelTaps", .label = "Vogel taps",
         .help = "Bilinear compares of the Vogel-disc filter (three.js: 5); more smooth the per-pixel noise at a linear cost.",
         .unit = "taps", .kind = K::Int, .min = 1, .max = 64, .step = 1, .shader = "vogelTaps", ST_FIELD_ACCESS(filter.vogelTaps)},
        {.path = "filter.radius", .label = "Vogel radius",
         .help = "Radius of the Vogel-disc filter in texels (three.js shadow.radius); 0 = one 2x2 compare, larger is softer and noisier.",
         .unit = "texels", .kind = K::Float, .min = 0, .max = 32, .step = 0.1, .shader = "filterRadius", ST_FIELD_ACCESS(filter.radius)},
        {.path = "filter.screenSpace", .label = "Screen-space blur",
         .help = "blur: seed 001's path, the filter's factor per pixel downsampled, blurred, upsampled and read by the main pass.",
         .kind = K::Enum, .enumNames = enumNames<ScreenSpace>(), ST_FIELD_ACCESS(filter.screenSpace)},
        {.path = "filter.screenDownsample", .label = "Screen blur downsample",
         .help = "The mask is blurred at 1/N of the output size (2: half, seed 001): larger is cheaper and softer, blockier at edges.",
         .unit = "x", .kind = K::Int, .min = 1, .max = 4, .step = 1, .powerOfTwo = true, ST_FIELD_ACCESS(filter.screenDownsample)},
        {.path = "filter.screenBlurRadius", .label = "Screen blur radius",
         .help = "Downsampled pixels each side of the screen-space Gaussian, sigma (r + 1) / 2: wider softens more; 0 = no blur.",
         .unit = "px", .kind = K::Int, .min = 0, .max = 16, .step = 1, ST_FIELD_ACCESS(filter.screenBlurRadius)},
        {.path = "filter.screenDepthSigma", .label = "Screen blur depth sigma",
         .help = "Depth step (share of view depth) where a blur tap's weight is 0.61: smaller stops bleeding over silhouettes; 0 = off.",
         .unit = "of depth", .kind = K::Float, .min = 0, .max = 10, .step = 0.01, ST_FIELD_ACCESS(filter.screenDepthSigma)},
        {.path = "filter.contact", .label = "Contact shadows",
         .help = "march: a short screen-space march toward the sun near each receiver; puts back contacts a bias detaches.",
         .kind = K::Enum, .enumNames = enumNames<ContactShadows>(), ST_FIELD_ACCESS(filter.contact)},
        {.path = "filter.contactLength", .label = "Contact length",
         .help = "Metres marched toward the sun from each receiver: longer closes wider gaps, with more false shadow.",
         .unit = "m", .kind = K::Float, .min = 0.01, .max = 10, .step = 0.01, ST_FIELD_ACCESS(filter.contactLength)},
        {.path = "filter.contactSteps", .label = "Contact steps",
         .help = "Depth-buffer samples along the march: more find thinner casters at a linear cost per pixel.",
         .unit = "taps", .kind = K::Int, .min = 2, .max = 64, .step = 1, ST_FIELD_ACCESS(filter.contactSteps)},
        {.path = "filter.contactThickness", .label = "Contact thickness",
         .help = "Metres behind the visible surface a march sample still counts as inside a caster; thin casters need less.",
         .unit = "m", .kind = K::Float, .min = 0.001, .max = 10, .step = 0.01, ST_FIELD_ACCESS(filter.contactThickness)},
        {.path = "bias.constant", .label = "Constant bias",
         .help = "Moves receivers toward the light against acne; too much detaches shadows. Negative: away (three.js shadowBias).",
         .unit = "m", .kind = K::Float, .min = -10, .max = 10, .step = 0.001, .shader = "biasConstant", ST_FIELD_ACCESS(bias.constant)},
        {.path = "bias.constantUnit", .label = "Constant bias unit",
         .help = "metres; or depth: a share of each light box's depth (three.js shadowBias, Babylon.js bias), more metres in deeper boxes.",
         .kind = K::Enum, .enumNames = enumNames<BiasUnit>(), .shader = "biasUnit", ST_FIELD_ACCESS(bias.constantUnit)},
        {.path = "bias.slope", .label = "Slope bias",
         .help = "Bias that grows with the tangent of the angle to the light, where acne is worst.",
         .unit = "texels", .kind = K::Float, .min = 0, .max = 100, .step = 0.01, .shader = "biasSlope", ST_FIELD_ACCESS(bias.slope)},
        {.path = "bias.normalOffset", .label = "Normal offset",
         .help = "Moves receivers along their normal, removing acne with less peter-panning than depth bias.",
         .unit = "texels", .kind = K::Float, .min = 0, .max = 100, .step = 0.01, .shader = "normalOffset", ST_FIELD_ACCESS(bias.normalOffset)},
        {.path = "bias.normalOffsetUnit", .label = "Normal offset unit",
         .help = "texels: grows with each cascade's texel; metres: one distance for all (three.js, Babylon.js normalBias).",
         .kind = K::Enum, .enumNames = enumNames<OffsetUnit>(), .shader = "normalOffsetUnit", ST_FIELD_ACCESS(bias.normalOffsetUnit)},
        {.path = "bias.normalOffsetSide", .label = "Normal offset moves",
         .help = "The receiver out along its normal, or the caster into its surface by the offset x sin(normal, sun) (Babylon.js).",
         .kind = K::Enum, .enumNames = enumNames<NormalOffsetSide>(), ST_FIELD_ACCESS(bias.normalOffsetSide)},
        {.path = "bias.receiverPlane", .label = "Receiver-plane bias",
         .help = "Derives depth bias from screen-space depth derivatives, which suits large filter kernels.",
         .kind = K::Bool, .shader = "receiverPlane", ST_FIELD_ACCESS(bias.receiverPlane)},
        // Factors, not per-cascade values: the global bias stays the one knob an artist turns (the
        // factors follow it), an empty list is today's behaviour, and a tuner searches a unitless
        // number near 1 per cascade whatever the scene's scale.
        {.path = "bias.constantScale", .label = "Constant bias per cascade",
         .help = "Factor of the constant bias per cascade, 1 = as set above (far cascades' larger texels may need more); empty = 1s.",
         .unit = "x", .kind = K::FloatList, .min = 0, .max = 100, .step = 0.01, ST_FIELD_ACCESS(bias.constantScale)},
        {.path = "bias.slopeScale", .label = "Slope bias per cascade",
         .help = "Factor of the slope bias per cascade, 1 = as set above: trades acne for peter-panning in one cascade; empty = 1 for all.",
         .unit = "x", .kind = K::FloatList, .min = 0, .max = 100, .step = 0.01, ST_FIELD_ACCESS(bias.slopeScale)},
        {.path = "bias.normalOffsetScale", .label = "Normal offset per cascade",
         .help = "Factor of the normal offset for each cascade (1 = as set above); empty = 1 for all.",
         .unit = "x", .kind = K::FloatList, .min = 0, .max = 100, .step = 0.01, ST_FIELD_ACCESS(bias.normalOffsetScale)},
    };
}

std::vector<FieldInfo> outputRows() {
    return {
        {.path = "output.width", .label = "Width",
         .help = "Output image width; image comparisons and metrics are computed at this resolution.",
         .unit = "px", .kind = K::Int, .min = 16, .max = 8192, .step = 1, .change = C::Output,
         ST_FIELD_ACCESS(output.width)},
        {.path = "output.height", .label = "Height",
         .help = "Output image height; image comparisons and metrics are computed at this resolution.",
         .unit = "px", .kind = K::Int, .min = 16, .max = 8192, .step = 1, .change = C::Output,
         ST_FIELD_ACCESS(output.height)},
        {.path = "output.view", .label = "View",
         .help = "Shaded, cascade colours, shadow term, pixels per texel, side view of the light boxes, or a texel "
                 "checker per map.",
         .kind = K::Enum, .enumNames = enumNames<View>(), .shader = "viewMode", ST_FIELD_ACCESS(output.view)},
        {.path = "output.texelBlock", .label = "Texel block",
         .help = "Texel-grid view: checker squares of this many texels a side; their size shows each map's resolution.",
         .unit = "texels", .kind = K::Int, .min = 1, .max = 256, .step = 1, .shader = "texelBlock",
         ST_FIELD_ACCESS(output.texelBlock)},
        {.path = "output.sideTexels", .label = "Texels in world",
         .help = "Side view: each shadow texel drawn at the world point it stores, in its cascade's tint (seed 003).",
         .kind = K::Bool, ST_FIELD_ACCESS(output.sideTexels)},
    };
}

std::vector<FieldInfo> pathRows() {
    return {
        {.path = "path.frames", .label = "Path frames",
         .help = "Frames the cascade camera takes along the path while the observer stays; 0 = no path.",
         .unit = "frames", .kind = K::Int, .min = 0, .max = 10000, .step = 1, .change = C::None,
         ST_FIELD_ACCESS(path.frames)},
        {.path = "path.keyframes", .label = "Path keyframes",
         .help = "Poses (position, target, fovY) the cascade camera passes through, to measure flicker.",
         .kind = K::KeyframeList, .change = C::None, ST_FIELD_ACCESS(path.keyframes)},
    };
}

std::vector<FieldInfo> measureRows() {
    return {
        {.path = "measure.sunRays", .label = "Sun rays",
         .help = "Rays per pixel over the sun's disc for the soft ground truth; more rays give smoother true penumbrae at linear cost.",
         .unit = "rays", .kind = K::Int, .min = 1, .max = 1024, .step = 1, .change = C::None,
         ST_FIELD_ACCESS(measure.sunRays)},
        {.path = "measure.artifactTexels", .label = "Artifact distance",
         .help = "Light more than k texels inside a true shadow is bleeding; light within k texels of a contact is peter-panning.",
         .unit = "texels", .kind = K::Float, .min = 0, .max = 64, .step = 0.1, .change = C::None,
         ST_FIELD_ACCESS(measure.artifactTexels)},
    };
}

#undef ST_FIELD_ACCESS

std::vector<FieldInfo> buildTable() {
    std::vector<FieldInfo> table;
    for (auto&& rows : {sceneAndCameraRows(), lightRows(), cascadeSplitRows(), cascadeFitRows(),
                        filterAndBiasRows(), outputRows(), pathRows(), measureRows()}) {
        table.insert(table.end(), rows.begin(), rows.end());
    }
    return table;
}

}  // namespace

const std::vector<FieldInfo>& fieldTable() {
    static const std::vector<FieldInfo> table = buildTable();
    return table;
}

const FieldInfo* findField(std::string_view path) {
    const auto& table = fieldTable();
    const auto it = std::find_if(table.begin(), table.end(), [&](const FieldInfo& f) { return f.path == path; });
    return it == table.end() ? nullptr : &*it;
}

std::vector<const FieldInfo*> changedFields(const Settings& a, const Settings& b) {
    std::vector<const FieldInfo*> changed;
    for (const FieldInfo& field : fieldTable()) {
        if (field.get(a) != field.get(b)) changed.push_back(&field);
    }
    return changed;
}

ChangeClass classifyChange(const Settings& a, const Settings& b) {
    ChangeClass worst = ChangeClass::None;
    for (const FieldInfo* field : changedFields(a, b)) worst = std::max(worst, field->change);
    return worst;
}

std::string_view changeClassName(ChangeClass change) {
    switch (change) {
        case ChangeClass::None: return "none";
        case ChangeClass::Uniform: return "uniform";
        case ChangeClass::Reallocate: return "reallocate";
        case ChangeClass::Output: return "output";
        case ChangeClass::Scene: return "scene";
    }
    return "<invalid>";
}

std::string_view fieldKindName(FieldKind kind) {
    switch (kind) {
        case FieldKind::Float: return "float";
        case FieldKind::Int: return "int";
        case FieldKind::Bool: return "bool";
        case FieldKind::Enum: return "enum";
        case FieldKind::String: return "string";
        case FieldKind::Vec3: return "vec3";
        case FieldKind::FloatList: return "float list";
        case FieldKind::IntList: return "int list";
        case FieldKind::KeyframeList: return "keyframe list";
    }
    return "<invalid>";
}

}  // namespace st
