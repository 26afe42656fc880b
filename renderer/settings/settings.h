#pragma once
// The one value everything tunable lives in: the editor edits it, presets serialise it, the
// renderer consumes it and headless replay loads it. No GL, no JSON here: plain data only.
// Every field listed here has a row in field_table.cpp (label, range, unit, help); a field that
// is missing there is a bug (tests/settings checks the table covers the JSON round trip).
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace st {

enum class SplitScheme { Uniform, Logarithmic, Practical, Manual };
// Cascade: tight light-space AABB of each slice (crop matrix, seeds 000/002).
// Scene: every cascade starts at the camera near plane (seed 004 "fit to scene").
// Sphere: bounding sphere of the slice, size constant under rotation (seed 001).
enum class FitMode { Cascade, Scene, Sphere };
// How far the light box reaches toward the light beyond the slice itself.
// Pancake: no extension, casters in front are clamped onto the near plane (depth clamp, seed 001).
enum class ZExtension { None, Distance, SceneBounds, Pancake };
enum class Selection { Interval, Map };  // seed 004: view depth vs first map that contains the point
enum class FilterKind { Hard, Pcf2x2, PcfNxN };
// TexelDensity: screen pixels per shadow texel as a heat map (blue < 1/4 wasted, green 1 ideal,
// red > 1 perspective aliasing; docs/architecture.md#texel-density).
// Side: the frame from an outside orbit camera with the main frustum, its split planes and each
// cascade's light box as wireframes.
enum class View { Shaded, Cascades, Shadow, TexelDensity, Side };

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
    bool operator==(const LightSettings&) const = default;
};

struct CascadeSettings {
    int count = 4;                         // 1..8
    SplitScheme scheme = SplitScheme::Practical;
    float lambda = 0.5f;                   // seed 000: 1 = fully logarithmic, 0 = uniform
    std::vector<float> manualSplits;       // view-depth ends of cascades 0..count-2, metres, increasing
    float shadowDistance = 0.0f;           // metres; 0 = camera far plane
    int mapSize = 1024;                    // texels per side, power of two 256..8192
    FitMode fit = FitMode::Cascade;
    bool stabilize = false;                // snap the light box to whole texels (seed 001)
    ZExtension zExtension = ZExtension::SceneBounds;
    float zExtensionDistance = 100.0f;     // metres, for ZExtension::Distance
    Selection selection = Selection::Interval;
    float blendBand = 0.0f;                // fraction of a cascade's depth range blended into the next, 0..0.5
    bool operator==(const CascadeSettings&) const = default;
};

struct FilterSettings {
    FilterKind kind = FilterKind::Pcf2x2;
    int size = 3;  // taps per side for PcfNxN, odd, 3..9
    bool operator==(const FilterSettings&) const = default;
};

struct BiasSettings {
    float constant = 0.02f;     // metres along the light direction
    float slope = 1.0f;         // texel world sizes per unit of tan(angle to light)
    float normalOffset = 0.0f;  // receiver moved along its normal, in texel world sizes
    bool receiverPlane = false; // derivative-based receiver-plane depth bias (seed 004)
    bool operator==(const BiasSettings&) const = default;
};

struct OutputSettings {
    int width = 640;
    int height = 360;
    View view = View::Shaded;
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

struct Settings {
    std::string scene = "builtin:yard";  // "builtin:NAME" or a glTF path relative to the preset
    std::string notes;                   // free text: what of the source system is not reproduced
    bool ground = false;                 // a ground quad under a glTF scene that has none (SceneOptions)
    CameraSettings camera;
    LightSettings light;
    CascadeSettings cascades;
    FilterSettings filter;
    BiasSettings bias;
    OutputSettings output;
    PathSettings path;
    bool operator==(const Settings&) const = default;
};

}  // namespace st
