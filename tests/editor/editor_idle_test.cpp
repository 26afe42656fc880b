// Issue 21 #2 on the real window under Xvfb: once the editor has settled (the scene drawn, the
// Accuracy panel's figures in), it draws no frame until something happens: none in 2 s of
// nobody touching it; a mouse move over the window wakes it, and Ctrl+C still closes it. The
// A/B split settles the same way once A's figures are in.
// Frames are counted by the editor (--status-file), not timed.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {
nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in, nullptr, false);
}
}  // namespace

TEST(EditorIdleTest, ASettledEditorDrawsNothingUntilAnEventComes) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1 && command -v xdotool >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "xvfb-run or xdotool missing (scripts/setup.sh installs xvfb and xdotool)";
    const fs::path dir = fs::temp_directory_path() / ("st-idle-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "config" / "shadowtune");
    std::ofstream(dir / "config" / "shadowtune" / "window.json") << R"({"width": 1000, "height": 700})";
    const fs::path status = dir / "status.json";
    // Copies of the status file taken at the moments the test compares (the editor rewrites it).
    std::ofstream(dir / "drive.sh")
        << "set -u\n"
           "'" ST_SHADOWTUNE "' editor '" ST_PRESET_DIR "/dx-sdk-csm11.json' --status-file '" << status.string()
        << "' > '" << (dir / "editor.txt").string() << "' 2>&1 &\n"
           "pid=$!\n"
           "for i in $(seq 3000); do grep -q '\"idle\": *true' '" << status.string() << "' 2>/dev/null && break; sleep 0.1; done\n"
           "cp '" << status.string() << "' idle-start.json\n"
           "sleep 2\n"
           "cp '" << status.string() << "' idle-end.json\n"
           "xdotool mousemove 500 350; sleep 0.2; xdotool mousemove 520 360; sleep 1\n"
           "cp '" << status.string() << "' woken.json\n"
           // Compare > Set as A (Ctrl+Shift+A) turns the split on: once A's figures are in, it idles too.
           "xdotool keydown ctrl keydown shift; sleep 0.3; xdotool keydown a; sleep 0.3; xdotool keyup a; sleep 0.1; "
           "xdotool keyup shift keyup ctrl; sleep 0.5\n"
           "for i in $(seq 3000); do grep -q '\"idle\": *true' '" << status.string() << "' && break; sleep 0.1; done\n"
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
