#pragma once
#include <filesystem>
#include <optional>

namespace st::app {

struct CompareOptions {
    std::filesystem::path a, b;       // preset files
    std::filesystem::path outDir;     // required
    // Default: B's cascades, filter and bias are measured on A's scene, camera, light and path,
    // so both see the same pixels. With keepBScene, B keeps its own scene, camera, light and path.
    bool keepBScene = false;
    std::optional<int> width, height;  // both at this size (default: A's output size)
    int costFrames = 5;                // timed frames for the cost figures, after a warm-up
#ifdef NDEBUG
    bool debugContext = false;         // KHR_debug; any serious message fails the comparison
#else
    bool debugContext = true;
#endif
};

// Measures both presets and writes OUT/side-by-side.png, split.png, shadow-diff.png (when both
// see the same view) and compare.json, then prints the table of figures and deltas. Both presets
// are read and checked before anything is created; any failure writes nothing. Returns the exit
// code: 0; 1 when a preset (or B on A's view) is invalid, or the GL context or a measurement
// failed; 2 when the output folder cannot be created.
int runCompare(const CompareOptions& opt);

}  // namespace st::app
