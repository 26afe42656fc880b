// The real editor window under Xvfb: it must start, draw panels and the scene, and exit 0; its
// Accuracy panel must come up with the figures `measure` gives for the same frame.
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "tests/support/image_compare.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;

namespace {
int countNear(const st::Rgba8Image& img, int r, int g, int b, int tol) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size() / 4; ++i)
        n += std::abs(img.pixels[i * 4] - r) <= tol && std::abs(img.pixels[i * 4 + 1] - g) <= tol &&
             std::abs(img.pixels[i * 4 + 2] - b) <= tol;
    return n;
}
}  // namespace

TEST(EditorSmokeTest, WindowUnderXvfbShowsPanelsAndScene) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run missing (scripts/setup.sh installs xvfb)";
    fs::path dir = fs::temp_directory_path() / ("st-editor-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path shot = dir / "editor.png";
    std::string cmd = "XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" ST_SHADOWTUNE
                      "' editor '" ST_PRESET_DIR "/default.json' --frames 4 --debug-gl --screenshot '" +
                      shot.string() + "' > '" + (dir / "log.txt").string() + "' 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << "editor failed, see " << (dir / "log.txt");
    st::Rgba8Image img = st::readImage(shot);
    EXPECT_EQ(img.width, 1280);
    EXPECT_EQ(img.height, 800);  // the first launch fills the screen's work area (no window manager: all of it)
    EXPECT_GT(countNear(img, 158, 184, 217, 6), 20000) << "no sky: scene not drawn";   // clear colour, sRGB
    EXPECT_GT(countNear(img, 21, 22, 23, 4) + countNear(img, 15, 15, 15, 4), 2000) << "no ImGui panel";
    EXPECT_TRUE(fs::exists(dir / "imgui.ini") || fs::exists(dir / "shadowtune" / "imgui.ini"));
    fs::remove_all(dir);
}

TEST(EditorSmokeTest, PresetSavedFromEditorReplaysHeadlessToTheSameImage) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run missing (scripts/setup.sh installs xvfb)";
    fs::path dir = fs::temp_directory_path() / ("st-replay-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string log = " > '" + (dir / "log.txt").string() + "' 2>&1";
    std::string editor = "XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" ST_SHADOWTUNE
                         "' editor '" ST_PRESET_DIR "/dx-sdk-csm11.json' --frames 3 --scene-screenshot '" +
                         (dir / "editor.png").string() + "' --save-as '" + (dir / "saved.json").string() + "'" + log;
    ASSERT_EQ(std::system(editor.c_str()), 0) << "editor failed, see " << (dir / "log.txt");
    std::string replay = "'" ST_SHADOWTUNE "' render '" + (dir / "saved.json").string() + "' --out '" +
                         (dir / "replay").string() + "'" + log;
    ASSERT_EQ(std::system(replay.c_str()), 0) << "replay failed, see " << (dir / "log.txt");
    st::Rgba8Image fromEditor = st::readImage(dir / "editor.png");
    st::Rgba8Image replayed = st::readImage(dir / "replay" / "saved.png");
    st::test::CompareResult r = st::test::compareImages(replayed, fromEditor, {});  // renderdiff tolerance
    EXPECT_TRUE(r.pass) << r.summary();
    // Issue 21 #8: the scripted save dropped "$schema"; it names the source's schema file, first,
    // as File > Save as writes it (the source's "../schema/preset.schema.json", from /tmp here).
    std::ifstream in(dir / "saved.json");
    const nlohmann::ordered_json saved = nlohmann::ordered_json::parse(in, nullptr, false);
    ASSERT_TRUE(saved.is_object() && !saved.empty()) << "see " << dir / "saved.json";
    EXPECT_EQ(saved.begin().key(), "$schema") << saved.dump(2);
    ASSERT_TRUE(saved.contains("$schema") && saved["$schema"].is_string()) << saved.dump(2);
    const fs::path schema = saved["$schema"].get<std::string>();
    EXPECT_TRUE(fs::exists(dir / schema)) << schema;
    if (fs::exists(dir / schema))
        EXPECT_TRUE(fs::equivalent(dir / schema, fs::path(ST_PRESET_DIR) / "../schema/preset.schema.json")) << schema;
    fs::remove_all(dir);
}

namespace {

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// "misclassified 1.234% (false shadow ...; gross N px)": the part of the summary that `measure`
// and the editor's --wait-accuracy print alike.
std::string accuracyFigures(const std::string& log) {
    const auto from = log.find("misclassified ");
    const auto to = log.find(" px)", from);
    return from == std::string::npos || to == std::string::npos ? "" : log.substr(from, to + 4 - from);
}

// "520x383" from "accuracy: done in 1.23 s (520x383): ...".
std::string sceneSize(const std::string& log) {
    const auto done = log.find("accuracy: done in");
    const auto from = log.find('(', done), to = log.find(')', from);
    return done == std::string::npos || to == std::string::npos ? "" : log.substr(from + 1, to - from - 1);
}

}  // namespace

// The Accuracy panel on the real window: after the camera has been still, the background ground
// truth ends, its figures are those `measure` gives for the same frame, and its error overlay is
// drawn over the scene once switched on (--error-overlay: it is off by default). Bias off, so acne
// covers the ground in the overlay's magenta.
TEST(EditorSmokeTest, AccuracyPanelShowsMeasuredFiguresAndOverlayOnceStill) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run missing (scripts/setup.sh installs xvfb)";
    fs::path dir = fs::temp_directory_path() / ("st-accuracy-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path preset = dir / "acne.json";
    st::Settings s = st::loadPreset(ST_PRESET_DIR "/default.json");
    s.bias.constant = 0.0f;
    s.bias.slope = 0.0f;
    st::savePresetAtomic(s, preset);
    const fs::path shot = dir / "editor.png", log = dir / "log.txt";
    std::string editor = "XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" ST_SHADOWTUNE
                         "' editor '" + preset.string() + "' --frames 2 --wait-accuracy --error-overlay --debug-gl --screenshot '" +
                         shot.string() + "' > '" + log.string() + "' 2>&1";
    ASSERT_EQ(std::system(editor.c_str()), 0) << "editor failed, see " << log;
    const std::string editorLog = readText(log);
    ASSERT_NE(editorLog.find("accuracy: done in"), std::string::npos) << editorLog;
    EXPECT_NE(editorLog.find("against the sun's disc (0.53 deg, 16 rays): filtered error"), std::string::npos)
        << "the panel's soft-truth figures";

    // The scene viewport the panels leave ("accuracy: done in 1.23 s (520x383)"), measured at its size.
    const std::string size = sceneSize(editorLog);
    ASSERT_FALSE(size.empty()) << editorLog;
    const std::string measure = "'" ST_SHADOWTUNE "' measure '" + preset.string() + "' --size " + size + " --no-flicker "
                                "--frames 1 --out '" + (dir / "measure").string() + "' > '" + (dir / "measure.txt").string() + "' 2>&1";
    ASSERT_EQ(std::system(measure.c_str()), 0) << "measure failed, see " << (dir / "measure.txt");
    const std::string figures = accuracyFigures(editorLog);
    EXPECT_FALSE(figures.empty()) << editorLog;
    EXPECT_EQ(figures, accuracyFigures(readText(dir / "measure.txt")));

    st::Rgba8Image img = st::readImage(shot);
    ASSERT_EQ(img.width, 1280);
    EXPECT_GT(countNear(img, 220, 20, 200, 4), 5000) << "no false-shadow overlay over the scene";
    fs::remove_all(dir);
}

// Issue 39 #6: a light box that cuts casters off says so in the editor, as `render` warns, not only as
// the figures panel's orange "!". The status file carries the lines the panels show.
TEST(EditorSmokeTest, CutCastersAreWarnedWhereTheArtistLooks) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run missing (scripts/setup.sh installs xvfb)";
    fs::path dir = fs::temp_directory_path() / ("st-cut-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path status = dir / "status.json", log = dir / "log.txt";
    const std::string editor = "XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" ST_SHADOWTUNE
                               "' editor '" ST_PRESET_DIR "/scenarios/tower-no-extension.json' --frames 3 --status-file '" +
                               status.string() + "' > '" + log.string() + "' 2>&1";
    ASSERT_EQ(std::system(editor.c_str()), 0) << "editor failed, see " << log;
    const std::string text = readText(status);
    EXPECT_NE(text.find("warning: cascade 0: z-extension 0 m cuts casters up to"), std::string::npos) << text;
    fs::remove_all(dir);
}

// Issue 13 #1: --save-as into another folder used to keep "../../../shared/assets/..." as it was,
// so `render` of the saved file failed with "scene file not found".
TEST(EditorSmokeTest, SaveAsIntoAnotherFolderWritesAPresetThatRenders) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run missing (scripts/setup.sh installs xvfb)";
    const fs::path source = ST_PRESET_DIR "/scenes/fox.json";
    if (!fs::exists(source.parent_path() / st::loadPreset(source).scene)) GTEST_SKIP() << "../shared/assets missing";
    fs::path dir = fs::temp_directory_path() / ("st-saveas-" + std::to_string(::getpid()));
    fs::create_directories(dir / "a" / "b");
    const std::string log = " > '" + (dir / "log.txt").string() + "' 2>&1";
    const std::string editor = "XDG_CONFIG_HOME='" + dir.string() + "' xvfb-run -a -s '-screen 0 1280x800x24' '" ST_SHADOWTUNE
                               "' editor '" + source.string() + "' --frames 2 --save-as '" +
                               (dir / "a" / "b" / "fox.json").string() + "'" + log;
    ASSERT_EQ(std::system(editor.c_str()), 0) << "editor failed, see " << (dir / "log.txt");
    const std::string render = "'" ST_SHADOWTUNE "' render '" + (dir / "a" / "b" / "fox.json").string() +
                               "' --size 160x90 --out '" + (dir / "out").string() + "'" + log;
    EXPECT_EQ(std::system(render.c_str()), 0) << "render of the saved preset failed, see " << (dir / "log.txt");
    EXPECT_TRUE(fs::exists(dir / "out" / "fox.png"));
    EXPECT_TRUE(fs::path(st::loadPreset(dir / "a" / "b" / "fox.json").scene).is_relative());
    fs::remove_all(dir);
}
