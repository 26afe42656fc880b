// Replays one preset at a small size and compares it with its reviewed golden image.
//   golden_check PRESET GOLDEN_DIR ARTIFACT_DIR [--skip-without-assets]
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
#include "tests/support/image_compare.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

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

int check(const fs::path& preset, const fs::path& goldenDir, const fs::path& artifactDir) {
    auto ctx = HeadlessContext::create(true);
    gpu::enableDebugOutput();
    Rgba8Image actual = renderPreset(preset);
    if (gpu::seriousDebugMessageCount() > 0) {
        std::fprintf(stderr, "FAIL %s: GL debug output reported errors\n", preset.string().c_str());
        return 1;
    }
    fs::path golden = goldenDir / (preset.stem().string() + ".png");
    const char* update = std::getenv("ST_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writeImageAtomic(golden, actual);
        std::printf("updated %s\n", golden.string().c_str());
        return 0;
    }
    if (!fs::exists(golden)) {
        std::fprintf(stderr, "FAIL: no golden %s (run ./test.sh --update-goldens, then review it)\n",
                     golden.string().c_str());
        return 1;
    }
    test::Tolerance tol;  // 5/255 per channel, 0.1 % of pixels (Filament's renderdiff)
    test::CompareResult r = test::compareImages(actual, readImage(golden), tol);
    std::printf("%s: %s\n", preset.stem().string().c_str(), r.summary().c_str());
    if (r.pass) return 0;
    fs::create_directories(artifactDir);
    std::string stem = preset.stem().string();
    writeImageAtomic(artifactDir / (stem + ".actual.png"), actual);
    if (r.sizeMatches) writeImageAtomic(artifactDir / (stem + ".diff.png"), test::diffImage(actual, readImage(golden), tol));
    std::fprintf(stderr, "FAIL %s: see %s\n", stem.c_str(), artifactDir.string().c_str());
    return 1;
}
}  // namespace

bool sceneMissing(const fs::path& preset) {
    Settings s = loadPreset(preset);
    return s.scene.rfind("builtin:", 0) != 0 && !fs::exists(preset.parent_path() / s.scene);
}

int main(int argc, char** argv) {
    bool skipWithoutAssets = argc == 5 && std::string(argv[4]) == "--skip-without-assets";
    if (argc != 4 && !skipWithoutAssets) {
        std::fprintf(stderr, "usage: golden_check PRESET GOLDEN_DIR ARTIFACT_DIR [--skip-without-assets]\n");
        return 2;
    }
    try {
        if (skipWithoutAssets && sceneMissing(argv[1])) {
            std::printf("SKIP %s: its scene is not there (../shared/assets beside the project?)\n", argv[1]);
            return 77;
        }
        return check(argv[1], argv[2], argv[3]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "FAIL %s: %s\n", argv[1], e.what());
        return 1;
    }
}
