#pragma once
#include "renderer/export/engine_export.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace st::app {

struct EditorOptions {
    std::optional<std::filesystem::path> preset;  // default: <presetDir>/default.json if present
    std::filesystem::path presetDir = "presets";  // the editor command passes defaultPresetDir()
    int frames = 0;                                // > 0: quit after N frames (smoke tests)
    std::optional<std::filesystem::path> screenshot;  // written after the last frame
    std::optional<std::filesystem::path> sceneShot;   // the scene view alone, after the last frame
    std::optional<std::filesystem::path> saveAs;      // "Save As" after the last frame (scripted runs)
    float orbitDegPerFrame = 0.0f;  // scripted camera motion: turn around the target about +Y (benchmarks)
    std::vector<int> hover;  // {x, y}: the mouse is put there every frame (scripted probe screenshots)
    std::optional<std::filesystem::path> layoutReport;  // JSON: the scene viewport and every panel's rectangle
    // Rewritten after every frame: {"pid", "frames" drawn, "idle": the editor waits for an event,
    // drawing nothing, "accuracy": the Accuracy panel's summary line, "split": the A/B split is
    // shown, "camera", "title": the window's, which names the preset open}. What tests and the
    // idle benchmark watch.
    std::optional<std::filesystem::path> statusFile;
    bool previewPath = false;   // View > Preview path on the first frame; with frames, run until it plays
    bool waitAccuracy = false;  // with frames: the last frame waits for the Accuracy panel's figures
    bool errorOverlay = false;  // the Accuracy panel's error overlay on from the start (scripted screenshots)
    bool debugContext = false;
    std::optional<xport::Engine> engine;  // --engine: the Engine section's choice at start
};

// Runs the editor until the window closes; returns the exit code.
int runEditor(const EditorOptions& opt);

}  // namespace st::app
