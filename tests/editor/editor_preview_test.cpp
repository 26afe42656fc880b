// Preview path in the real editor under Xvfb (issue 21 #3): it renders the preset's path at the
// scene viewport's full size and plays it, and the flicker F it reports is `measure`'s for the
// same preset at that size (an independent run of the headless command).
#include "renderer/image/image_io.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace {
std::string readText(const fs::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(EditorPreviewTest, PreviewPathPlaysTheFullSizePathWithMeasuresFlicker) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run missing (scripts/setup.sh installs xvfb)";
    const fs::path dir = fs::temp_directory_path() / ("st-preview-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "shadowtune");
    std::ofstream(dir / "shadowtune" / "window.json") << R"({"width": 1000, "height": 700})";
    const std::string preset = ST_PRESET_DIR "/scenarios/shimmer-unstable.json";  // a path, and flicker to measure
    const std::string editor = "XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" ST_SHADOWTUNE
                               "' editor '" + preset + "' --preview-path --frames 2 --debug-gl --scene-screenshot '" +
                               (dir / "scene.png").string() + "' > '" + (dir / "editor.txt").string() + "' 2>&1";
    ASSERT_EQ(std::system(editor.c_str()), 0) << "see " << dir / "editor.txt";
    const std::string log = readText(dir / "editor.txt");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, std::regex(R"(Preview path \(the preset's path, 16 frames at full quality\): playing, flicker F ([0-9.]+) %)")))
        << log;
    const std::string previewF = m[1];
    // The last frame rendered is the path's last, at the viewport's full size (not an interactive one).
    const st::Rgba8Image scene = st::readImage(dir / "scene.png");
    ASSERT_GT(scene.width, 200);
    ASSERT_GT(scene.height, 200);

    const std::string size = std::to_string(scene.width) + "x" + std::to_string(scene.height);
    const std::string measure = "'" ST_SHADOWTUNE "' measure '" + preset + "' --size " + size + " --out '" +
                                (dir / "measure").string() + "' > '" + (dir / "measure.txt").string() + "' 2>&1";
    ASSERT_EQ(std::system(measure.c_str()), 0) << "see " << dir / "measure.txt";
    const std::string measured = readText(dir / "measure.txt");
    ASSERT_TRUE(std::regex_search(measured, m, std::regex(R"(flicker F ([0-9.]+)%)"))) << measured;
    EXPECT_EQ(previewF, std::string(m[1])) << "the preview's F at " << size << " is measure's";
    EXPECT_NE(previewF, "0.000") << "the unstable control flickers";
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}
