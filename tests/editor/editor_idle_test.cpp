// Issue 21 #2 on the real window under Xvfb: once the editor has settled (the scene drawn, the
// Accuracy panel's figures in), it draws no frame until something happens: none in 2 s of
// nobody touching it; a mouse move over the window wakes it, and Ctrl+C still closes it. The
// A/B split settles the same way once A's figures are in.
// Frames are counted by the editor (--status-file), not timed.
#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {
// Shell for the drive scripts: `settled FILE` waits until the editor is idle, having drawn a frame
// since FILE was copied (under load the status file may still hold the idle state from before the
// input); `settled` alone waits for the first idle state.
const char* kSettled =
    "frames() { sed -n 's/.*\"frames\": *\\([0-9]*\\).*/\\1/p' \"$1\" 2>/dev/null; }\n"
    "settled() {\n"
    "  for i in $(seq 3000); do\n"
    "    if grep -q '\"idle\": *true' status.json 2>/dev/null && { [ $# -eq 0 ] || [ \"$(frames status.json)\" != \"$(frames \"$1\")\" ]; }; then return; fi\n"
    "    sleep 0.1\n"
    "  done\n"
    "}\n";

nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in, nullptr, false);
}
// A fresh folder whose config gives the editor a 1000x700 window.
fs::path freshWindowDir(const std::string& prefix) {
    const fs::path dir = fs::temp_directory_path() / (prefix + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "config" / "shadowtune");
    std::ofstream(dir / "config" / "shadowtune" / "window.json") << R"({"width": 1000, "height": 700})";
    return dir;
}

// The drive script's start: the editor on dx-sdk-csm11 in the background, then wait until it settles.
std::string launchSettled(const fs::path& dir, const fs::path& status) {
    return std::string("set -u\n") + kSettled + "'" ST_SHADOWTUNE "' editor '" ST_PRESET_DIR "/dx-sdk-csm11.json' --status-file '" +
           status.string() + "' > '" + (dir / "editor.txt").string() + "' 2>&1 &\npid=$!\nsettled\n";
}
}  // namespace

TEST(EditorIdleTest, ASettledEditorDrawsNothingUntilAnEventComes) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1 && command -v xdotool >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "xvfb-run or xdotool missing (scripts/setup.sh installs xvfb and xdotool)";
    const fs::path dir = freshWindowDir("st-idle-");
    const fs::path status = dir / "status.json";
    // Copies of the status file taken at the moments the test compares (the editor rewrites it).
    std::ofstream(dir / "drive.sh")
        << launchSettled(dir, status) <<
           "cp '" << status.string() << "' idle-start.json\n"
           "sleep 2\n"
           "cp '" << status.string() << "' idle-end.json\n"
           "xdotool mousemove 500 350; sleep 0.2; xdotool mousemove 520 360; sleep 1\n"
           "cp '" << status.string() << "' woken.json\n"
           // Compare > Set as A (Ctrl+Shift+A) turns the split on: once A's figures are in, it idles too.
           "xdotool keydown ctrl keydown shift; sleep 0.3; xdotool keydown a; sleep 0.3; xdotool keyup a; sleep 0.1; "
           "xdotool keyup shift keyup ctrl; sleep 0.5\n"
           "settled woken.json\n"
           "cp '" << status.string() << "' split-start.json\n"
           "sleep 1\n"
           "cp '" << status.string() << "' split-end.json\n"
           "kill -INT $pid\n"
           "for i in $(seq 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done\n"
           "kill -0 $pid 2>/dev/null && { kill -KILL $pid; exit 102; }\n"
           "wait $pid\n";
    const std::string cmd = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
                            "' xvfb-run -a -s '-screen 0 1280x800x24' bash drive.sh > drive.txt 2>&1";
    const int code = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(code));
    EXPECT_EQ(WEXITSTATUS(code), 0) << "102: Ctrl+C did not close the idle editor; see " << dir / "drive.txt" << " and "
                                    << dir / "editor.txt";
    const nlohmann::json start = readJson(dir / "idle-start.json"), end = readJson(dir / "idle-end.json"),
                         woken = readJson(dir / "woken.json");
    ASSERT_TRUE(start.is_object() && end.is_object() && woken.is_object()) << "no status file; see " << dir / "editor.txt";
    ASSERT_TRUE(start.value("idle", false)) << "the editor never settled: " << start.dump();
    EXPECT_GT(start.value("frames", 0), 0);
    EXPECT_EQ(start.value("accuracy", "").rfind("accuracy: done in", 0), 0u)
        << "idle before the Accuracy panel's job ended: " << start.dump();
    EXPECT_EQ(end.value("frames", -1), start.value("frames", -2)) << "frames drawn while nothing happened";
    EXPECT_TRUE(end.value("idle", false));
    EXPECT_GT(woken.value("frames", 0), end.value("frames", 0)) << "a mouse move over the window did not wake it";
    // Issue 21 #10: the A/B split rendered every frame with nothing touched.
    const nlohmann::json splitStart = readJson(dir / "split-start.json"), splitEnd = readJson(dir / "split-end.json");
    ASSERT_TRUE(splitStart.is_object() && splitEnd.is_object());
    EXPECT_TRUE(splitStart.value("split", false)) << "Ctrl+Shift+A did not turn the split on: " << splitStart.dump();
    EXPECT_TRUE(splitStart.value("idle", false)) << "the split never settled: " << splitStart.dump();
    EXPECT_EQ(splitEnd.value("frames", -1), splitStart.value("frames", -2)) << "frames drawn with the split on and nothing touched";
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

// Issue 21 #3: Alt + left drag orbits the camera around the point under the cursor, on the real
// window with xdotool: 100 px to the right turns the view 0.4 rad (0.004 rad a pixel, as the fly's
// look), the camera keeps its distance to its target, and the drag is one undo step (the title's
// unsaved marker, so the editor is killed at the end rather than asked to close).
TEST(EditorOrbitTest, AltDragOrbitsTheCamera) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1 && command -v xdotool >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "xvfb-run or xdotool missing (scripts/setup.sh installs xvfb and xdotool)";
    const fs::path dir = freshWindowDir("st-orbit-");
    const fs::path status = dir / "status.json";
    std::ofstream(dir / "drive.sh")
        << launchSettled(dir, status) <<
           "cp '" << status.string() << "' before.json\n"
           // Over the scene viewport (1000x700: the columns leave x 340..740), resting so the probe reads it.
           "xdotool mousemove 540 200; sleep 1\n"
           "xdotool keydown alt; sleep 0.3; xdotool mousedown 1; sleep 0.3\n"
           "for i in $(seq 10); do xdotool mousemove_relative 10 0; sleep 0.05; done\n"
           "sleep 0.3; xdotool mouseup 1; sleep 0.2; xdotool keyup alt; sleep 0.5\n"
           "settled before.json\n"
           "cp '" << status.string() << "' after.json\n"
           "kill -KILL $pid; wait $pid; exit 0\n";
    const std::string cmd = "cd '" + dir.string() + "' && XDG_CONFIG_HOME='" + (dir / "config").string() +
                            "' xvfb-run -a -s '-screen 0 1280x800x24' bash drive.sh > drive.txt 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << "see " << dir / "drive.txt";
    const nlohmann::json before = readJson(dir / "before.json"), after = readJson(dir / "after.json");
    ASSERT_TRUE(before.contains("camera") && after.contains("camera")) << "see " << dir / "editor.txt";
    auto vec = [](const nlohmann::json& v) { return glm::vec3(v[0].get<float>(), v[1].get<float>(), v[2].get<float>()); };
    const glm::vec3 p0 = vec(before["camera"]["position"]), t0 = vec(before["camera"]["target"]);
    const glm::vec3 p1 = vec(after["camera"]["position"]), t1 = vec(after["camera"]["target"]);
    EXPECT_GT(glm::length(p1 - p0), 0.1f) << "the camera did not move";
    EXPECT_NEAR(glm::length(t1 - p1), glm::length(t0 - p0), 1e-3f * glm::length(t0 - p0)) << "orbit keeps the view's length";
    const glm::vec3 f0 = glm::normalize(t0 - p0), f1 = glm::normalize(t1 - p1);
    EXPECT_NEAR(std::atan2(f1.x, -f1.z) - std::atan2(f0.x, -f0.z), 0.4f, 0.02f) << "100 px of drag";
    EXPECT_NEAR(f1.y, f0.y, 0.01f) << "a level drag keeps the pitch";
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}
