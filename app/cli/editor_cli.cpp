// `shadowtune editor`: the interactive tuning window.
#include "app/cli/commands.h"
#include "app/cli/number_checks.h"
#include "app/editor/editor_app.h"
#include "app/preset_dir.h"
#include "renderer/export/engine_knobs.h"

#include <memory>

namespace st::app {

void addEditorCommand(CLI::App& cli, int& exitCode) {
    auto opt = std::make_shared<EditorOptions>();
    auto preset = std::make_shared<std::string>();
    auto engine = std::make_shared<std::string>();
    CLI::App* editor = cli.add_subcommand("editor", "Open the interactive editor (needs a display)");
    editor->add_option("preset", *preset, "Preset to open (default: default.json of presets/, or of the installed presets)");
    editor->add_option("--frames", opt->frames, "Quit after N frames (for scripted runs)")->check(numberIn(1, 1000000));
    editor->add_option("--screenshot", opt->screenshot, "Write the window to this PNG after the last frame");
    editor->add_option("--scene-screenshot", opt->sceneShot, "Write the scene view alone (no panels) after the last frame");
    editor->add_option("--save-as", opt->saveAs, "Save the settings as a preset after the last frame");
    editor->add_option("--hover", opt->hover, "X,Y: keep the mouse at this window position (probe screenshots)")
        ->expected(2)->delimiter(',');
    editor->add_option("--orbit", opt->orbitDegPerFrame,
                       "DEG: turn the camera around its target by DEG degrees every frame (a scripted moving-camera benchmark)")
        ->check(numberIn(-45.0f, 45.0f));
    editor->add_flag("--preview-path", opt->previewPath,
                     "Start View > Preview path on the first frame; with --frames, keep drawing until it plays, then print its line");
    editor->add_option("--layout-report", opt->layoutReport,
                       "Write the scene viewport's and the panels' and widgets' rectangles (JSON) after the last frame");
    editor->add_option("--status-file", opt->statusFile,
                       "Rewrite this JSON after every frame: the process id, frames drawn, and whether the editor is idle "
                       "(waiting for input, drawing nothing)");
    editor->add_flag("--wait-accuracy", opt->waitAccuracy,
                     "With --frames: keep drawing until the Accuracy panel shows its figures, then print them");
    editor->add_flag("--error-overlay", opt->errorOverlay,
                     "Start with the Accuracy panel's error overlay on (magenta false shadow, cyan false light; off by default)");
    editor->add_option("--engine", *engine,
                       "Open in engine mode: the Settings panel shows this engine's knobs and greys what it lacks; the Tune "
                       "panel tunes in its knobs (" + xport::knobEngineList() + ")")
        ->check(CLI::Validator(
            [](std::string& name) {  // every engine with a knob table
                return xport::parseKnobEngine(name) ? std::string() : "'" + name + "' is not one of " + xport::knobEngineList();
            },
            "ENGINE"));
    editor->add_flag("--debug-gl", opt->debugContext, "Debug context; GL messages are printed");
    editor->callback([opt, preset, engine, &exitCode] {
        if (!preset->empty()) opt->preset = *preset;
        if (!engine->empty()) opt->engine = xport::parseKnobEngine(*engine);
        opt->presetDir = defaultPresetDir(opt->preset.value_or(std::filesystem::path()));
        exitCode = runEditor(*opt);
    });
}

}  // namespace st::app
