// Sweep files: strict reading with the file, JSON path and reason; the grid, ids and shards.
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_schema.h"
#include "sweep/sweep_spec.h"
#include "tests/sweep/sweep_test_util.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>

using namespace st;
using namespace st::sweep;

namespace {
const char* kBase = R"({"version": 1, "scene": "builtin:box-over-plane", "output": {"width": 64, "height": 36}})";

std::string messagesOf(const std::filesystem::path& file) {
    try {
        loadSweep(file);
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(SweepSpecTest, AxesExpandToEveryCombinationLastAxisFastest) {
    test::TempDir dir;
    dir.write("base.json", kBase);
    const auto file = dir.write("s.json", R"({"version": 1, "base": "base.json",
        "axes": [{"field": "cascades.count", "values": [1, 2]},
                 {"field": "cascades.lambda", "range": {"from": 0.5, "to": 0.95, "step": 0.15}}]})");
    const SweepSpec spec = loadSweep(file);
    ASSERT_EQ(spec.axes.size(), 2u);
    EXPECT_EQ(spec.axes[1].valueText, (std::vector<std::string>{"0.5", "0.65", "0.8", "0.95"}));
    const std::vector<Point> points = expandPoints(spec);
    ASSERT_EQ(points.size(), 8u);
    EXPECT_EQ(points[0].label, "count=1 lambda=0.5");
    EXPECT_EQ(points[1].label, "count=1 lambda=0.65");
    EXPECT_EQ(points[4].label, "count=2 lambda=0.5");
    EXPECT_EQ(points[7].settings.cascades.count, 2);
    EXPECT_FLOAT_EQ(points[7].settings.cascades.lambda, 0.95f);
    std::set<std::string> ids;
    for (const Point& p : points) ids.insert(p.id);
    EXPECT_EQ(ids.size(), points.size()) << "every point has its own id";
    EXPECT_EQ(expandPoints(loadSweep(file))[5].id, points[5].id) << "ids are stable between reads";
}

TEST(SweepSpecTest, ReferencesTakeTheirMethodOntoTheBase) {
    test::TempDir dir;
    dir.write("base.json", kBase);
    dir.write("ref.json", R"({"version": 1, "scene": "builtin:yard", "camera": {"fovY": 30},
        "cascades": {"count": 3, "mapSize": 512}, "filter": {"kind": "hard"}, "bias": {"constant": 0.5}})");
    const SweepSpec spec = loadSweep(dir.write("s.json", R"({"version": 1, "base": "base.json",
        "set": {"cascades.mapSize": 2048}, "references": ["ref.json"]})"));
    const std::vector<Point> points = expandPoints(spec);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_TRUE(points[0].reference);
    EXPECT_EQ(points[0].label, "ref");
    EXPECT_EQ(points[0].settings.scene, "builtin:box-over-plane");  // the base's scene and camera
    EXPECT_FLOAT_EQ(points[0].settings.camera.fovY, 60.0f);
    EXPECT_EQ(points[0].settings.cascades.count, 3);  // the reference's method
    EXPECT_EQ(points[0].settings.cascades.mapSize, 512);
    EXPECT_EQ(points[0].settings.filter.kind, FilterKind::Hard);
    EXPECT_EQ(spec.base.cascades.mapSize, 2048);  // "set" applies to the base
}

// The shipped sweeps put seed presets chosen for a 400 m view on 60 m and 300 m scenes: a reference
// whose range is past the base's far plane ends there, its manual splits in proportion, and says so.
TEST(SweepSpecTest, AReferencePastTheFarPlaneEndsThereAndKeepsItsSplitProportions) {
    test::TempDir dir;
    dir.write("base.json", R"({"version": 1, "scene": "builtin:box-over-plane", "camera": {"farPlane": 60},
        "output": {"width": 64, "height": 36}})");
    dir.write("far.json", R"({"version": 1, "camera": {"farPlane": 1000}, "cascades": {"count": 3,
        "scheme": "manual", "manualSplits": [20, 80], "shadowDistance": 400}})");
    dir.write("near.json", R"({"version": 1, "camera": {"farPlane": 200}, "cascades": {"count": 2,
        "scheme": "manual", "manualSplits": [30], "shadowDistance": 50}})");
    const SweepSpec spec = loadSweep(dir.write("s.json", R"({"version": 1, "base": "base.json",
        "references": ["far.json", "near.json"]})"));
    const std::vector<Point> points = expandPoints(spec);
    ASSERT_EQ(points.size(), 2u);
    const CascadeSettings& far = points[0].settings.cascades;
    EXPECT_FLOAT_EQ(far.shadowDistance, 0.0f) << "ends at the base's far plane";
    ASSERT_EQ(far.manualSplits.size(), 2u);
    EXPECT_FLOAT_EQ(far.manualSplits[0], 3.0f);  // 20 of 400 m is 3 of 60 m
    EXPECT_FLOAT_EQ(far.manualSplits[1], 12.0f);
    EXPECT_FLOAT_EQ(points[1].settings.cascades.shadowDistance, 50.0f) << "a reference that fits is kept";
    EXPECT_FLOAT_EQ(points[1].settings.cascades.manualSplits[0], 30.0f);
    ASSERT_EQ(spec.adapted.size(), 1u);
    EXPECT_NE(spec.adapted[0].find("far: shadow range 400 m is past this scene's far plane (60 m)"), std::string::npos)
        << spec.adapted[0];
    EXPECT_NE(spec.adapted[0].find("20 m -> 3 m 80 m -> 12 m"), std::string::npos) << spec.adapted[0];
}

TEST(SweepSpecTest, ShardsSplitThePointsWithoutOverlap) {
    std::vector<Point> points(10);
    for (int i = 0; i < 10; ++i) points[std::size_t(i)].id = std::to_string(i);
    std::multiset<std::string> seen;
    for (int k = 1; k <= 3; ++k)
        for (const Point& p : shardOf(points, k, 3)) seen.insert(p.id);
    EXPECT_EQ(seen.size(), 10u);
    EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), 10u);
    EXPECT_EQ(shardOf(points, 2, 3).front().id, "1");
}

TEST(SweepSpecTest, BadFilesNameTheFileThePathAndTheReason) {
    test::TempDir dir;
    dir.write("base.json", kBase);
    const auto check = [&](const std::string& body, const std::string& want) {
        const auto file = dir.write("bad.json", body);
        const std::string got = messagesOf(file);
        EXPECT_NE(got.find(file.string() + ": " + want), std::string::npos) << "got: " << got << "\nwant: " << want;
    };
    check(R"({"version": 1, "base": "base.json", "axes": [{"field": "cascades.colour", "values": [1]}]})",
          "axes[0].field: unknown field \"cascades.colour\"");
    check(R"({"version": 1, "base": "base.json", "axes": [{"field": "cascades.mapSize", "values": [512, 1000]}]})",
          "axes[0].values[1]: must be a power of two");
    check(R"({"version": 1, "base": "base.json", "axes": [{"field": "cascades.fit", "range": {"from": 0, "to": 2, "step": 1}}]})",
          "axes[0].range: a range needs a number field");
    check(R"({"version": 1, "base": "base.json", "axes": [{"field": "cascades.count", "values": [1]},
          {"field": "cascades.count", "values": [2]}]})", "axes[1].field: sweeps cascades.count twice");
    check(R"({"version": 1, "base": "base.json", "axes": [{"field": "scene", "values": ["builtin:yard"]}]})",
          "axes[0].field: \"scene\" cannot be swept");
    check(R"({"version": 1, "base": "base.json", "colour": 1, "axes": [{"field": "cascades.count", "values": [1]}]})",
          "colour: unknown key");
    check(R"({"version": 2, "base": "base.json", "axes": [{"field": "cascades.count", "values": [1]}]})", "version: must be 1");
    check(R"({"version": 1, "base": "nowhere.json"})", "base: ");
    check(R"({"version": 1, "base": "base.json", "set": {"cascades.scheme": "manual"},
          "axes": [{"field": "cascades.count", "values": [2]}]})", "axes: point count=2: cascades.manualSplits");
    check(R"({"version": 1, "base": "base.json"})", "axes: a sweep needs at least one axis or reference");
    EXPECT_NE(messagesOf(dir.write("broken.json", "{\"version\": 1,")).find("broken.json:1:"), std::string::npos);
}

// A range's count is reckoned in double and checked before it becomes an integer: a huge count
// (which once read "gives -9223372036854775808 values") and one that overflows to infinity are
// both refused with the JSON path, the count and the limit. The largest allowed count is not run
// (expanding 100000 points takes seconds); AxesExpandToEveryCombinationLastAxisFastest has a
// range that passes.
TEST(SweepSpecTest, AHugeRangeCountIsRefusedWithTheCountAndTheLimit) {
    test::TempDir dir;
    dir.write("base.json", kBase);
    const auto range = [&](const std::string& from, const std::string& to, const std::string& step) {
        return messagesOf(dir.write("range.json", R"({"version": 1, "base": "base.json", "axes": [{"field": "cascades.lambda", "range": {"from": )" +
                                                      from + ", \"to\": " + to + ", \"step\": " + step + "}}]}"));
    };
    const std::string file = (dir.path() / "range.json").string();
    EXPECT_EQ(range("0", "1e30", "1"), file + ": axes[0].range: gives 1e+30 values, more than the 100000 a sweep may have");
    EXPECT_EQ(range("-1e308", "1e308", "1e-300"),
              file + ": axes[0].range: gives more than 1e+308 values, more than the 100000 a sweep may have");
    EXPECT_EQ(range("0", "1", "0.00001"), file + ": axes[0].range: gives 100001 values, more than the 100000 a sweep may have");
}

// schema/sweep.schema.json is generated from the field table; ST_UPDATE_SCHEMA=1 rewrites it.
TEST(SweepSchemaTest, SchemaFileIsTheGeneratedOne) {
    const std::filesystem::path file = ST_SOURCE_DIR "/schema/sweep.schema.json";
    const std::string want = sweepJsonSchemaText();
    if (const char* update = std::getenv("ST_UPDATE_SCHEMA"); update && std::string(update) == "1")
        std::ofstream(file, std::ios::binary) << want;
    std::ifstream in(file, std::ios::binary);
    const std::string got{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_TRUE(got == want) << file << " is stale or missing: run ST_UPDATE_SCHEMA=1 " << "ctest -R SweepSchemaTest and commit it";
    const auto schema = nlohmann::json::parse(want);
    EXPECT_EQ(schema["properties"]["version"]["const"], kSweepVersion);
    bool hasCount = false;
    for (const auto& axis : schema["properties"]["axes"]["items"]["oneOf"])
        hasCount = hasCount || axis["properties"]["field"]["const"] == "cascades.count";
    EXPECT_TRUE(hasCount);
}
