// Suite files: what they hold once read, and every kind of error naming file, JSON path and reason.
#include "check/suite_file.h"
#include "check/suite_schema.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>

namespace fs = std::filesystem;
using namespace st::check;

namespace {
struct Folder {
    fs::path dir;
    Folder() {
        dir = fs::temp_directory_path() / ("st_suite_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir / "presets");
        for (const char* name : {"a.json", "b.json", "c.txt"}) std::ofstream(dir / "presets" / name) << "{}";
    }
    ~Folder() { fs::remove_all(dir); }
    fs::path write(const std::string& text) const {
        std::ofstream(dir / "suite.json") << text;
        return dir / "suite.json";
    }
};

// The error of loading `text`: "<json path>: <reason>".
std::string errorOf(const Folder& f, const std::string& text) {
    try {
        loadSuite(f.write(text));
    } catch (const SuiteError& e) {
        EXPECT_EQ(e.file(), f.dir / "suite.json");
        return e.jsonPath() + ": " + e.reason();
    }
    return "no error";
}
}  // namespace

TEST(SuiteFileTest, GlobsDefaultsAndEntriesMerge) {
    Folder f;
    const Suite s = loadSuite(f.write(R"({"version": 1,
        "defaults": {"size": "160x90", "image": {"max_channel_diff": 3},
                     "figures": [{"figure": "misclassified", "worse_by_at_most_pp": 0.05}, {"figure": "flicker", "max": 0}]},
        "presets": ["presets/*.json",
                    {"preset": "presets/b.json", "note": "n", "image": {"max_failing_share": 0.01},
                     "figures": [{"figure": "accuracy.misclassified", "worse_by_at_most_pp": 0.5},
                                 {"figure": "softFilteredError", "worse_by_at_most_factor": 1.1}]}]})"));
    ASSERT_EQ(s.entries.size(), 2u);  // c.txt does not match; b listed twice is one entry
    const SuiteEntry& a = s.entries[0];
    const SuiteEntry& b = s.entries[1];
    EXPECT_EQ(a.name, "a");
    EXPECT_EQ(b.name, "b");
    ASSERT_TRUE(a.size);
    EXPECT_EQ(a.size->first, 160);
    EXPECT_EQ(a.image.maxChannelDiff, 3);
    EXPECT_DOUBLE_EQ(a.image.maxFailingShare, 0.001);  // the built-in default
    EXPECT_DOUBLE_EQ(b.image.maxFailingShare, 0.01);
    EXPECT_EQ(b.image.maxChannelDiff, 3);              // from the defaults
    ASSERT_EQ(a.figures.size(), 2u);
    ASSERT_EQ(b.figures.size(), 3u);                   // misclassified replaced, flicker kept, soft added
    EXPECT_EQ(b.figures[0].row->key, "accuracy.misclassified");
    EXPECT_DOUBLE_EQ(b.figures[0].limit, 0.5);
    EXPECT_EQ(b.figures[1].row->key, "flicker.flipRate");
    EXPECT_EQ(b.figures[2].row->key, "soft.filteredError");
    EXPECT_EQ(b.figures[2].rule, FigureRule::WorseByAtMostFactor);
    EXPECT_EQ(b.note, "n");
    EXPECT_EQ(selectEntries(s.entries, "b*").size(), 1u);
    EXPECT_EQ(selectEntries(s.entries, "").size(), 2u);
}

TEST(SuiteFileTest, ErrorsNameThePathAndTheReason) {
    Folder f;
    EXPECT_EQ(errorOf(f, R"({"version": 2, "presets": ["presets/a.json"]})"),
              "/version: unsupported version 2 (this program reads 1)");
    EXPECT_EQ(errorOf(f, R"({"version": 1})"), "/presets: missing: the presets to check");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "presets": ["presets/nope.json"]})"),
              "/presets/0: no such preset: " + (f.dir / "presets/nope.json").string());
    EXPECT_EQ(errorOf(f, R"({"version": 1, "presets": ["presets/*.png"]})"),
              "/presets/0: 'presets/*.png' matches no file in " + (f.dir / "presets").string());
    EXPECT_EQ(errorOf(f, R"({"version": 1, "presets": [{"preset": "presets/a.json", "figures": [{"figure": "nope", "max": 1}]}]})")
                  .substr(0, 38),
              "/presets/0/figures/0/figure: 'nope' is");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "presets": [{"preset": "presets/a.json", "figures": [{"figure": "filteredError", "max": 1}]}]})"),
              "/presets/0/figures/0/figure: 'filteredError' names more than one figure (accuracy.filteredError, "
              "soft.filteredError); give the key");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "defaults": {"figures": [{"figure": "flicker", "worse_by_at_most_factor": 0.5}]}, "presets": ["presets/a.json"]})"),
              "/defaults/figures/0/worse_by_at_most_factor: the factor must be >= 1");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "defaults": {"figures": [{"figure": "soft.filteredError", "worse_by_at_most_pp": 1}]}, "presets": ["presets/a.json"]})"),
              "/defaults/figures/0/worse_by_at_most_pp: soft.filteredError is not a share; worse_by_at_most_pp applies to shares only");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "defaults": {"figures": [{"figure": "cost.gpuMs", "max": 5}]}, "presets": ["presets/a.json"]})"),
              "/defaults/figures/0/max: cost.gpuMs is a measured time that differs between runs; it cannot be checked");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "defaults": {"figures": [{"figure": "flicker"}]}, "presets": ["presets/a.json"]})"),
              "/defaults/figures/0: give exactly one rule (max, min, worse_by_at_most, worse_by_at_most_pp, "
              "worse_by_at_most_factor), got 0");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "defaults": {"image": {"max_failing_share": 2}}, "presets": ["presets/a.json"]})"),
              "/defaults/image/max_failing_share: must be in 0..1, got 2");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "presets": [{"preset": "presets/a.json", "colour": 1}]})").substr(0, 32),
              "/presets/0/colour: unknown key (");
    EXPECT_EQ(errorOf(f, R"({"version": 1, "presets": [{"preset": "presets/a.json", "size": "big"}]})"),
              "/presets/0/size: expected WxH with 16..8192 each, got 'big'");
    EXPECT_EQ(errorOf(f, "{\"version\": 1,").substr(0, 16), ": not valid JSON");
}

TEST(SuiteFileTest, TwoPresetsOfOneNameAreRefused) {
    Folder f;
    fs::create_directories(f.dir / "other");
    std::ofstream(f.dir / "other/a.json") << "{}";
    EXPECT_NE(errorOf(f, R"({"version": 1, "presets": ["presets/a.json", "other/a.json"]})").find("two presets are named 'a'"),
              std::string::npos);
}

// schema/suite.schema.json is generated; ST_UPDATE_SCHEMA=1 rewrites it.
TEST(SuiteSchemaTest, SchemaFileIsTheGeneratedOne) {
    const fs::path file = ST_SOURCE_DIR "/schema/suite.schema.json";
    const std::string want = suiteJsonSchemaText();
    if (const char* update = std::getenv("ST_UPDATE_SCHEMA"); update && std::string(update) == "1")
        std::ofstream(file, std::ios::binary) << want;
    std::ifstream in(file, std::ios::binary);
    const std::string got{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_TRUE(got == want) << file << " is stale or missing: run ST_UPDATE_SCHEMA=1 ctest -R SuiteSchemaTest and commit it";
    const auto schema = nlohmann::json::parse(want);
    EXPECT_EQ(schema["properties"]["version"]["const"], kSuiteVersion);
    const auto& names = schema["$defs"]["figureTolerance"]["properties"]["figure"]["examples"];
    EXPECT_NE(std::find(names.begin(), names.end(), "flicker.flipRate"), names.end());
    EXPECT_EQ(std::find(names.begin(), names.end(), "cost.gpuMs"), names.end());  // a time cannot be checked
}
