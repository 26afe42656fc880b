#pragma once
// `shadowtune engine-check PRESET --engine threejs|babylon --out DIR`: the real engine (three.js or
// Babylon.js from npm, in headless Chromium; engines/README.md) renders the preset's view with the
// engine's own knobs, shadowtune renders its model of the same knobs (renderer/export/engine_knobs.h),
// and both are scored against the ray-cast truth: misclassified share, filtered error, and the
// share of pixels on which engine and model agree (metrics/engine_agreement.h).
#include "renderer/export/engine_knobs.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

struct EngineCheckOptions {
    std::filesystem::path preset;
    xport::Engine engine = xport::Engine::ThreeJs;
    std::filesystem::path outDir = "engine-check";
    std::optional<int> width, height;   // --size
    bool defaults = false;              // the engine's default knobs instead of the preset's export
    std::filesystem::path knobsFile;    // --knobs: a JSON object of the engine's knobs
    std::filesystem::path enginesDir;   // engines/ (run.mjs); empty: next to the sources
    std::vector<std::string> modelSets; // --model-set PATH=JSON: a field of the model changed (to see the check fail)
    bool quiet = false;                 // no figure table on stdout (a tune's proof prints its own)
    // The model rasterizes with the sub-pixel grid of the GPU the engine runs on: Chromium's
    // SwiftShader keeps 4 bits (WebGL SUBPIXEL_BITS), so 1/16 pixel; 0: this GPU's own (llvmpipe 8).
    int subpixelBits = 4;
#ifdef NDEBUG
    bool debugContext = false;
#else
    bool debugContext = true;
#endif
};

// Writes OUT/{engine,model,truth,disagreement}.png, figures.json, model.json (the model as a
// preset), job.json and engine.log; prints the figure table. Exit 0; 1 when the check failed;
// 2 when the engine cannot start (node, Chromium or the npm packages missing: the reason printed).
int runEngineCheck(const EngineCheckOptions& opt);

}  // namespace st::app
