#pragma once
// The end of `tune --engine threejs|babylon` (issue "Tune for your engine", item 3): the tuned
// knobs and the engine's defaults run in the real engine (engine-check) on every view of the tune,
// tuned and held out. The engine's own figures go into summary.json as an `engine` object and
// into explain.md as a table beside shadowtune's, so the tune's claim is proven in the engine.
#include "app/cli/tune_command.h"

#include <nlohmann/json.hpp>

#include <string>

namespace st::app {

struct EngineProof {
    bool ran = false;        // false: the engine is not one that runs here, or --no-engine-check
    std::string error;       // why the engine could not prove it (node, Chromium missing, ...)
    nlohmann::json summary;  // {"name", "version", "defaults": {"tuned", "heldOut"}, "tuned": {...}}
    std::string line;        // one line for stdout: defaults -> tuned, measured in the engine
};

// Runs the checks into OUT/engine-check/<defaults|tuned>/view-<i>/, then writes the `engine`
// object into OUT/summary.json and appends "In the engine itself" to OUT/explain.md (both
// rewritten atomically). A check that fails leaves `error` set and the tune's outputs as they were.
EngineProof proveInEngine(const TuneCommandOptions& opt);

}  // namespace st::app
