#pragma once
// What every engine mapping needs from a preset: its split depths, the end of the shadowed range
// and the texel world size of the first cascade, which converts texel-relative biases to metres.
#include "renderer/export/engine_export.h"
#include "renderer/settings/kind_descriptors.h"

#include <vector>

namespace st::xport {

struct PresetFacts {
    std::vector<float> splits;  // count + 1 view depths, metres (renderer/csm/splits.h)
    float nearPlane = 0.0f;     // camera near: where the first cascade starts
    float end = 0.0f;           // shadowDistance, or the camera far plane when it is 0
    std::vector<float> texel;   // metres per texel of each cascade as shadowtune fits it (light_fit.h)
};

// Uses the preset's own output aspect, fit and map size; the z extension does not change a
// texel's x,y size, so no scene is loaded (scene bounds are not needed).
PresetFacts presetFacts(const Settings& s);

// (z_i - near) / (end - near) for the interior splits i = 1..count-1: Godot, Filament, Unreal.
std::vector<double> fractionsOfRange(const PresetFacts& f);
// z_i / end for the interior splits: three.js breaks, Unity cascade splits.
std::vector<double> fractionsOfEnd(const PresetFacts& f);

double round6(double v);  // six significant decimals, so printed values do not carry float noise
nlohmann::json numbers(const std::vector<double>& v);

// The texel world size of the first cascade as text, for notes: "0.00885 m".
std::string texelNote(const PresetFacts& f);

// cascades.fadeBand fades the last fraction of the last cascade's range; engines state their fade as a
// share of the whole shadow distance: fadeBand x (end - start of the last cascade) / end.
double fadeShareOfEnd(const Settings& s, const PresetFacts& f);

// Per-cascade factors (bias.constantScale) equal, within 1 %, to the cascades' texel sizes over
// cascade 0's: a bias in texels of each cascade, as Unity URP and Unreal count theirs.
bool factorsFollowTexels(const std::vector<float>& factors, const PresetFacts& f);
// "filter.kind vsm": for the notes of an engine's filter item.
std::string filterKindText(const Settings& s);
// Settings no engine's shadow settings expose (depth-fitted splits, a map size per cascade, cascades
// redrawn every k frames, PCF padding, a bias per cascade, the debug one-frame-late matrices; the far
// fade where `engineFades` is false): one no-equivalent item each, only where the preset uses it, so
// an export never reads as complete when it is not.
void addShadowtuneOnly(EngineExport& e, const Settings& s, bool engineFades);
// What the preset uses and the engine lacks (EngineKnobs::lacks, "what: why"), one no-equivalent
// item "(what)" each: the web engines' exporters, from their knob tables.
void addLacks(EngineExport& e, const std::vector<std::string>& lacks);

// The knobs each engine answers in its own way: camera-relative light space, a fit field of view
// and contact shadows. Each exporter gives its engine's texts; an item is added only where the preset
// uses the knob. A knob whose engine has a setting for it is exported by that exporter itself
// (Godot's directional_shadow_min_fov, Unreal's and Filament's contact shadows) and its text here is
// empty.
struct KnobAnswers {
    std::string cameraRelative;  // the note of "(camera-relative light space)"
    std::string fitFovY;         // the note of "(fit field of view)"
    std::string contact;         // the note of "(contact shadows)"
};
void addKnobsWithoutSetting(EngineExport& e, const Settings& s, const KnobAnswers& a);

EngineExport exportGodot(const Settings& s, const PresetFacts& f);
EngineExport exportUnity(const Settings& s, const PresetFacts& f);
EngineExport exportUnreal(const Settings& s, const PresetFacts& f);
EngineExport exportBevy(const Settings& s, const PresetFacts& f);
EngineExport exportThreeJs(const Settings& s, const PresetFacts& f);
EngineExport exportFilament(const Settings& s, const PresetFacts& f);
EngineExport exportBabylon(const Settings& s, const PresetFacts& f);

}  // namespace st::xport
