// The sweep report from known point figures: the front, the CSV and loadable front presets.
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_results.h"
#include "tests/sweep/sweep_test_util.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace st;
using namespace st::sweep;

namespace {
PointResult point(const std::string& id, double gpuMs, double error, bool reference = false,
                  const std::string& scene = "builtin:box-over-plane") {
    Settings s;
    s.scene = scene;
    return {id, "p" + id, reference, {reference ? "" : id}, toOrderedJson(s),
            {{"accuracy.misclassified", error}, {"accuracy.filteredError", error / 10}, {"cost.gpuMs", gpuMs},
             {"cost.modelMs", gpuMs}, {"cost.mapBytes", 16.0 * (1 << 20)}}};
}

Manifest manifest(const std::vector<PointResult>& points, const std::filesystem::path& presetDir) {
    Manifest m;
    m.sweep = "t";
    m.scene = "builtin:box-over-plane";
    m.presetDir = presetDir;
    m.width = 64;
    m.height = 36;
    m.axisFields = {"cascades.count"};
    for (const auto& p : points) {
        m.pointIds.push_back(p.id);
        if (!p.reference) m.axisValues.resize(1), m.axisValues[0].push_back(p.id);
    }
    m.baseValues = {m.axisValues[0][0]};
    return m;
}

std::string read(const std::filesystem::path& f) {
    std::ifstream in(f);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
}  // namespace

TEST(SweepReportTest, FrontHoldsThePointsNoOtherDominates) {
    test::TempDir dir;
    // (time, error): 2 dominates 3 (faster and better); 1 and 4 trade time for error; 5 ties 4.
    const std::vector<PointResult> points = {point("1", 10, 5), point("2", 20, 2), point("3", 30, 3),
                                             point("4", 40, 1), point("5", 40, 1, true)};
    const auto front = writeReport(dir.path(), manifest(points, dir.path()), points, {});
    EXPECT_EQ(front, (std::vector<std::string>{"1", "2", "4", "5"}));
    const std::string csv = read(dir.path() / "results.csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    EXPECT_EQ(header.rfind("id,kind,label,cascades.count,accuracy.misclassified,accuracy.falseShadow,", 0), 0u) << header;
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);
    // Figures the points lack are empty cells; those they have sit in their table-order columns.
    std::string row5 = "5,reference,p5,";
    for (const metrics::FigureRow* r : metrics::figuresShown(metrics::InSweep)) {
        const double v = points[4].figure(r->key);
        row5 += ",";
        if (std::isfinite(v)) row5 += std::map<std::string, std::string>{
            {"accuracy.misclassified", "1"}, {"accuracy.filteredError", "0.1"}, {"cost.gpuMs", "40"},
            {"cost.modelMs", "40"}, {"cost.mapBytes", "16777216"}}.at(r->key);  // bytes as a whole number
    }
    EXPECT_NE(csv.find(row5 + "\n"), std::string::npos) << row5 << "\n" << csv;
    for (const char* f : {"pareto.png", "pareto.svg", "pareto-memory.png", "results.json", "front.json"})
        EXPECT_TRUE(std::filesystem::file_size(dir.path() / f) > 0) << f;
    const Settings saved = loadPreset(dir.path() / "front" / "2.json");  // a front point loads as a preset
    EXPECT_EQ(saved.scene, "builtin:box-over-plane");
}

TEST(SweepReportTest, FilteredErrorPicksItsOwnFront) {
    test::TempDir dir;
    std::vector<PointResult> points = {point("1", 10, 5), point("2", 20, 2)};
    points[1].figures[1].second = 0.9;  // point 2 is slower and worse by the filtered error
    const auto front = writeReport(dir.path(), manifest(points, dir.path()), points, {"filtered"});
    EXPECT_EQ(front, (std::vector<std::string>{"1"}));
}

TEST(SweepReportTest, FrontPresetsFindARelativeSceneFromTheirOwnFolder) {
    test::TempDir dir;
    dir.write("scenes/box.gltf", "{}");
    const auto presetDir = dir.path() / "presets" / "deep";
    const std::vector<PointResult> points = {point("1", 10, 5, false, "../../scenes/box.gltf")};
    writeReport(dir.path() / "out", manifest(points, presetDir), points, {});
    const nlohmann::json saved = nlohmann::json::parse(read(dir.path() / "out" / "front" / "1.json"));
    const std::filesystem::path scene = dir.path() / "out" / "front" / saved["scene"].get<std::string>();
    EXPECT_TRUE(std::filesystem::exists(scene)) << saved["scene"];
}

// Every --error choice names a figure a measured point has, the soft-truth ones their columns
// (raw values: shares as fractions).
TEST(SweepReportTest, EveryErrorChoiceIsAFigureOfAPoint) {
    metrics::PresetMeasurement m;
    m.soft.all.receivers = 200;
    m.soft.all.acne = 10;
    m.soft.all.lightBleeding = 4;
    m.soft.penumbra.truthPx = 3.0;
    m.soft.penumbra.filteredPx = 1.5;
    const Figures f = figuresOf(m);
    auto value = [&](const std::string& key) {
        for (const auto& [k, v] : f)
            if (k == key) return v;
        ADD_FAILURE() << key << " is not a figure";
        return 0.0;
    };
    for (const std::string& choice : errorChoices()) value(errorKey(choice));
    EXPECT_DOUBLE_EQ(value(errorKey("acne")), 0.05);
    EXPECT_DOUBLE_EQ(value(errorKey("light-bleeding")), 0.02);
    EXPECT_DOUBLE_EQ(value(errorKey("penumbra-width")), 1.5);
    EXPECT_DOUBLE_EQ(value("soft.penumbraWidth.errorPx"), -1.5);
    EXPECT_THROW(errorKey("sharpness"), std::invalid_argument);
}
