#pragma once
// Each engine's knobs as its own source text, to paste (`tune --engine`, the editor's Engine
// panel): built from the knob table (engine_knobs.h), so what is pasted is what the model renders
// and, for the engines that run here, what engine-check measures. Pure text, no GL.
#include "renderer/export/engine_export.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace st::xport {

// The knobs as the engine's own source text, to paste, one file each: three.js (`threejs.js`: the
// CSM addon and its lights), Babylon.js (`babylon.js`: the CascadedShadowGenerator's properties),
// Godot (`godot-light.tscn`: the DirectionalLight3D's property lines; `godot-project.godot`: the
// [rendering] settings of project.godot).
struct PasteText {
    std::string file;
    std::string text;
};
std::vector<PasteText> engineSnippets(Engine e, const nlohmann::json& knobs);

}  // namespace st::xport
