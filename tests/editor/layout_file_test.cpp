// The editor's layout file: what the user arranged comes back, and a broken file opens the
// editor with the default layout instead of failing (it is a preference, not a document).
#include "app/editor/layout_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {
fs::path scratch(const char* name) {
    const fs::path dir = fs::path(testing::TempDir()) / ("st-layout-file-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}
}  // namespace

TEST(LayoutFileTest, SavedPrefsComeBack) {
    const fs::path file = scratch("layout.json");
    st::ui::LayoutPrefs p;
    p.leftWidth = 512.0f;
    p.rightWidth = 287.5f;
    p.bottomHeight = 150.0f;
    p.panelsHidden = true;
    st::app::saveLayoutPrefs(file, p);
    EXPECT_EQ(st::app::loadLayoutPrefs(file), p);
    fs::remove_all(file.parent_path());
}

TEST(LayoutFileTest, MissingBrokenOrMistypedFilesGiveTheDefaults) {
    const st::ui::LayoutPrefs defaults;
    EXPECT_EQ(st::app::loadLayoutPrefs(scratch("none.json")), defaults);
    const fs::path file = scratch("broken.json");
    std::ofstream(file) << "{\"leftWidth\": 500,";
    EXPECT_EQ(st::app::loadLayoutPrefs(file), defaults);
    std::ofstream(file) << R"({"leftWidth": "wide", "panelsHidden": 1, "rightWidth": 250})";
    st::ui::LayoutPrefs expected;
    expected.rightWidth = 250.0f;  // the one member that is well typed
    EXPECT_EQ(st::app::loadLayoutPrefs(file), expected);
    fs::remove_all(file.parent_path());
}
