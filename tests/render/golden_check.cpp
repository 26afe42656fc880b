// Replays one preset at a small size and compares it with its reviewed golden image.
//   golden_check PRESET GOLDEN_DIR ARTIFACT_DIR [--tolerances FILE] [--skip-without-assets]
// --tolerances: the per-preset tolerance table (tests/render/golden_tolerances.json); without it
// every preset takes test::Tolerance's default. The tolerance in use and its reason are printed.
// --skip-without-assets: exit 77 (CTest "skipped") when the preset's scene file is absent, for
// presets of the third-party scenes in ../shared/assets, which a user's clone may not have.
// ST_UPDATE_GOLDENS=1 writes the golden instead (review the new images before committing).
// On failure the actual image and a diff image are left in ARTIFACT_DIR.
#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/image/image_io.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings_json.h"
#include "tests/support/golden_tolerance.h"
#include "tests/support/image_compare.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

namespace fs = std::filesystem;
using namespace st;

namespace {
// Small images keep the suite fast on two CPU cores; every preset keeps its own map size.
constexpr int kWidth = 320;
constexpr int kHeight = 180;

Rgba8Image renderPreset(const fs::path& preset) {
    Settings s = loadPreset(preset);
    s.output.width = kWidth;
    s.output.height = kHeight;
    Scene scene = loadScene(s.scene, preset.parent_path(), SceneOptions{.ground = s.ground});
    Renderer r(scene);
    r.render(s);
    return {r.width(), r.height(), r.readRgba8()};
}

struct Args {
    fs::path preset, goldenDir, artifactDir;
    std::optional<fs::path> tolerances;
    bool skipWithoutAssets = false;
};

std::optional<Args> parseArgs(int argc, char** argv) {
    if (argc < 4) return std::nullopt;
    Args a{argv[1], argv[2], argv[3], std::nullopt, false};
    for (int i = 4; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--skip-without-assets") a.skipWithoutAssets = true;
        else if (arg == "--tolerances" && i + 1 < argc) a.tolerances = argv[++i];
        else return std::nullopt;
    }
    return a;
}

test::GoldenTolerance toleranceOf(const Args& a) {
    if (!a.tolerances) return {test::Tolerance{}, "no --tolerances table given", false};
    return test::toleranceFor(test::readToleranceTable(*a.tolerances), a.preset.stem().string());
}

int check(const Args& a) {
    const fs::path& preset = a.preset;
    const fs::path& goldenDir = a.goldenDir;
    const fs::path& artifactDir = a.artifactDir;
    const test::GoldenTolerance golden = toleranceOf(a);  // a bad table fails before rendering
    auto ctx = HeadlessContext::create(true);
    gpu::enableDebugOutput();
    Rgba8Image actual = renderPreset(preset);
    if (gpu::seriousDebugMessageCount() > 0) {
        std::fprintf(stderr, "FAIL %s: GL debug output reported errors\n", preset.string().c_str());
        return 1;
    }
    const fs::path goldenFile = goldenDir / (preset.stem().string() + ".png");
    const char* update = std::getenv("ST_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writeImageAtomic(goldenFile, actual);
        std::printf("updated %s\n", goldenFile.string().c_str());
        return 0;
    }
    if (!fs::exists(goldenFile)) {
        std::fprintf(stderr, "FAIL: no golden %s (run ./test.sh --update-goldens, then review it)\n",
                     goldenFile.string().c_str());
        return 1;
    }
    const test::Tolerance& tol = golden.tolerance;
    std::printf("%s: tolerance %s\n", preset.stem().string().c_str(), golden.describe().c_str());
    test::CompareResult r = test::compareImages(actual, readImage(goldenFile), tol);
    std::printf("%s: %s\n", preset.stem().string().c_str(), r.summary().c_str());
    if (r.pass) return 0;
    fs::create_directories(artifactDir);
    std::string stem = preset.stem().string();
    writeImageAtomic(artifactDir / (stem + ".actual.png"), actual);
    if (r.sizeMatches) writeImageAtomic(artifactDir / (stem + ".diff.png"), test::diffImage(actual, readImage(goldenFile), tol));
    std::fprintf(stderr, "FAIL %s: see %s\n", stem.c_str(), artifactDir.string().c_str());
    return 1;
}
}  // namespace

bool sceneMissing(const fs::path& preset) {
    Settings s = loadPreset(preset);
    return s.scene.rfind("builtin:", 0) != 0 && !fs::exists(preset.parent_path() / s.scene);
}

int main(int argc, char** argv) {
    const std::optional<Args> args = parseArgs(argc, argv);
    if (!args) {
        std::fprintf(stderr, "usage: golden_check PRESET GOLDEN_DIR ARTIFACT_DIR [--tolerances FILE] "
                             "[--skip-without-assets]\n");
        return 2;
    }
    try {
        if (args->skipWithoutAssets && sceneMissing(args->preset)) {
            std::printf("SKIP %s: its scene is not there (../shared/assets beside the project?)\n", argv[1]);
            return 77;
        }
        return check(*args);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "FAIL %s: %s\n", argv[1], e.what());
        return 1;
    }
}
