// The figure table (metrics/figure_table.h): a known measurement reads back and formats right,
// every row shows up in every output its flags name, and a row added to the table shows up in
// all of them with no other edit.
#include "metrics/compare.h"
#include "metrics/figure_table.h"
#include "metrics/metrics_json.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_results.h"
#include "tests/sweep/sweep_test_util.h"

#include <fstream>
#include <set>
#include <sstream>

namespace st {
namespace {
using metrics::FigureRow;
using metrics::FigureTable;
using metrics::FigureUnit;
using OJson = nlohmann::ordered_json;

// Counts chosen so each figure has one known answer: 200 sun-facing pixels, 6 + 2 false shadow
// (edge + gross), 3 + 1 false light, |filtered - truth| summing to 10.
metrics::PresetMeasurement known() {
    metrics::PresetMeasurement m;
    metrics::ErrorCounts& a = m.accuracy.all;
    a.receivers = 200;
    a.falseShadowEdge = 6, a.falseShadowGross = 2, a.falseLightEdge = 3, a.falseLightGross = 1;
    a.filteredAbsErrorSum = 10.0;
    m.density.all = {100, 0.5, 1.5, 2.5, 4.0, 0.25, 0.125};
    metrics::ArtifactCounts& k = m.soft.all;
    k.receivers = 400;
    k.acne = 4, k.lightBleeding = 8, k.peterPanning = 2, k.missingCaster = 1, k.edge = 20;
    k.filteredAbsErrorSum = 20.0;
    m.soft.penumbra.truthPx = 3.0;
    m.soft.penumbra.filteredPx = 1.5;
    m.cost = metrics::CostReport{};
    m.cost->gpuShadowMs = 1.5, m.cost->gpuFilterMs = 0.25, m.cost->gpuMainMs = 2.0, m.cost->cpuMs = 0.5;
    m.cost->shadowMapBytes = 16u << 20, m.cost->filterMapBytes = 4u << 20;
    m.cost->triangles = 1200, m.cost->draws = 7, m.cost->sceneTriangles = 5000;
    m.cost->model = metrics::ModelledCost{{2.0, 1.0}, 3.0, 4.5, 0.5, 0.0, 8.0};
    m.cost->profile = "test profile";
    return m;  // no camera path: no flicker
}

std::optional<double> read(const metrics::PresetMeasurement& m, const std::string& key) {
    const FigureRow* row = metrics::findFigure(key);
    if (!row) throw std::runtime_error("no figure " + key);
    return row->read(m);
}

std::string formatted(const metrics::PresetMeasurement& m, const std::string& key) {
    return metrics::formatValue(metrics::findFigure(key)->unit, read(m, key));
}

TEST(FigureTableTest, KnownCountsReadBackAsTheirShares) {
    const auto m = known();
    EXPECT_DOUBLE_EQ(*read(m, "accuracy.misclassified"), 12.0 / 200.0);
    EXPECT_DOUBLE_EQ(*read(m, "accuracy.falseShadow"), 8.0 / 200.0);
    EXPECT_DOUBLE_EQ(*read(m, "accuracy.falseLight"), 4.0 / 200.0);
    EXPECT_DOUBLE_EQ(*read(m, "accuracy.edgeBand"), 9.0 / 200.0);
    EXPECT_DOUBLE_EQ(*read(m, "accuracy.grossShare"), 3.0 / 200.0);
    EXPECT_EQ(*read(m, "accuracy.grossPixels"), 3.0);
    EXPECT_EQ(*read(m, "accuracy.receivers"), 200.0);
    EXPECT_DOUBLE_EQ(*read(m, "accuracy.filteredError"), 0.05);
    EXPECT_EQ(*read(m, "texelDensity.p95"), 2.5);
    EXPECT_EQ(*read(m, "texelDensity.aliasingShare"), 0.25);
    EXPECT_FALSE(read(m, "flicker.flipRate")) << "no path, no flicker";
    EXPECT_DOUBLE_EQ(*read(m, "soft.acne"), 0.01);
    EXPECT_DOUBLE_EQ(*read(m, "soft.lightBleeding"), 0.02);
    EXPECT_DOUBLE_EQ(*read(m, "soft.filteredError"), 0.05);
    EXPECT_EQ(*read(m, "soft.penumbraWidth.errorPx"), -1.5);
    EXPECT_EQ(*read(m, "soft.penumbraWidth.absErrorPx"), 1.5);
    EXPECT_EQ(*read(m, "cost.gpuMs"), 3.75);
    EXPECT_EQ(*read(m, "cost.mapBytes"), double(20u << 20));
    EXPECT_EQ(*read(m, "cost.draws"), 7.0);
    EXPECT_EQ(*read(m, "cost.modelMs"), 8.0);
    EXPECT_EQ(*read(m, "cost.model.shadowMs"), 3.0);
    EXPECT_EQ(*read(m, "cost.model.mainMs"), 4.5);
    metrics::PresetMeasurement unmodelled = m;
    unmodelled.cost->model.reset();
    EXPECT_FALSE(read(unmodelled, "cost.modelMs")) << "no profile, no modelled cost";
    metrics::PresetMeasurement uncosted = m;
    uncosted.cost.reset();
    for (const FigureRow& r : metrics::figureTable())
        if (r.key.rfind("cost.", 0) == 0) EXPECT_FALSE(r.read(uncosted)) << r.key << ": no cost measured";
}

TEST(FigureTableTest, KnownValuesFormatWithTheirUnits) {
    const auto m = known();
    EXPECT_EQ(formatted(m, "accuracy.misclassified"), "6.000 %");
    EXPECT_EQ(formatted(m, "accuracy.filteredError"), "0.0500");
    EXPECT_EQ(formatted(m, "accuracy.grossPixels"), "3");
    EXPECT_EQ(formatted(m, "texelDensity.median"), "0.50");
    EXPECT_EQ(formatted(m, "soft.penumbraWidth.errorPx"), "-1.50 px");
    EXPECT_EQ(formatted(m, "cost.gpuMs"), "3.75 ms");
    EXPECT_EQ(formatted(m, "cost.mapBytes"), "20.0 MiB");
    EXPECT_EQ(formatted(m, "flicker.flipRate"), "-");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Share, 0.005), "+0.500 pp");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Bytes, 0.0), "±0 MiB");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Count, 0.0), "±0");
    EXPECT_DOUBLE_EQ(metrics::shown(FigureUnit::Bytes, double(3u << 20)), 3.0);
    EXPECT_EQ(metrics::figureJson(FigureUnit::Bytes, double(4u << 20)), 4 << 20);
}

TEST(FigureTableTest, RowsAreCompleteAndNamesUnique) {
    std::set<std::string> keys, errors, costs;
    for (const FigureRow& r : metrics::figureTable()) {
        SCOPED_TRACE(r.key);
        EXPECT_TRUE(keys.insert(r.key).second) << "duplicate key";
        EXPECT_FALSE(r.label.empty());
        EXPECT_FALSE(r.axisTitle.empty());
        EXPECT_FALSE(r.description.empty());
        EXPECT_TRUE(r.read);
        EXPECT_NE(r.shows, 0u);
        if (r.has(metrics::ErrorChoice)) EXPECT_TRUE(errors.insert(r.choice).second && !r.choice.empty());
        if (r.has(metrics::CostChoice)) EXPECT_TRUE(costs.insert(r.choice).second && !r.choice.empty());
        EXPECT_TRUE(r.choice.empty() || r.has(metrics::ErrorChoice) || r.has(metrics::CostChoice));
        EXPECT_TRUE(!r.timing || r.unit == FigureUnit::Ms) << "only measured times vary between runs";
    }
    // The names `sweep --error` took before the table keep working.
    for (const char* name : {"misclassified", "filtered", "flicker", "soft-filtered", "acne", "light-bleeding",
                             "peter-panning", "missing-caster", "penumbra-width"})
        EXPECT_TRUE(errors.count(name)) << name;
    EXPECT_EQ(sweep::errorKey("penumbra-width"), "soft.penumbraWidth.absErrorPx");
    EXPECT_EQ(sweep::costFigure("measured").key, "cost.gpuMs");
    EXPECT_EQ(sweep::costFigure("model").key, "cost.modelMs");
    EXPECT_EQ(sweep::costFigure(sweep::ReportOptions{}.cost).key, "cost.modelMs") << "fronts rank the modelled cost";
    EXPECT_EQ(sweep::costFigure(sweep::kMemoryChoice).key, "cost.mapBytes");
    EXPECT_THROW(sweep::errorKey("sharpness"), std::invalid_argument);
    EXPECT_THROW(sweep::costFigure("misclassified"), std::invalid_argument) << "an error is no cost";
}

// Every leaf of `detail` sits in `full` with the same value.
void expectKept(const OJson& detail, const OJson& full, const std::string& at) {
    if (!detail.is_object()) {
        EXPECT_EQ(detail, full) << at;
        return;
    }
    for (const auto& [k, v] : detail.items()) {
        ASSERT_TRUE(full.is_object() && full.contains(k)) << at << "/" << k;
        expectKept(v, full.at(k), at + "/" + k);
    }
}

TEST(FigureTableTest, MetricsJsonKeepsItsKeysAndHoldsEveryRowAtItsKey) {
    const auto m = known();
    const OJson full = metrics::toJson(m, "p");
    expectKept(metrics::toJson(m, "p", FigureTable{}), full, "");  // the rows change no existing value
    for (const FigureRow* r : metrics::figuresShown(metrics::InMetricsJson)) {
        SCOPED_TRACE(r->key);
        const OJson::json_pointer at(metrics::jsonPointer(r->key));
        if (!r->read(m)) {
            EXPECT_TRUE(!full.contains(at) || full.at(at).is_null());
            continue;
        }
        ASSERT_TRUE(full.contains(at));
        EXPECT_EQ(full.at(at), metrics::figureJson(r->unit, r->read(m)));
    }
    EXPECT_TRUE(full["flicker"].is_null()) << "an absent section stays null";
}

TEST(FigureTableTest, CompareListsEveryCompareRow) {
    const auto a = known();
    auto b = known();
    b.accuracy.all.falseShadowGross += 4;
    const auto figures = metrics::compareFigures(a, b);
    const OJson j = metrics::compareJson({"a", "b", "a.json", "b.json"}, figures, a, std::nullopt);
    const std::string table = metrics::compareTable({"a", "b", "a.json", "b.json"}, figures, std::nullopt);
    const auto rows = metrics::figuresShown(metrics::InCompare);
    ASSERT_EQ(figures.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        SCOPED_TRACE(rows[i]->key);
        EXPECT_EQ(figures[i].key, rows[i]->key);
        for (const char* side : {"a", "b", "delta"}) EXPECT_TRUE(j[side].contains(OJson::json_pointer(metrics::jsonPointer(rows[i]->key))));
        EXPECT_NE(table.find("\n" + rows[i]->label + " "), std::string::npos);
    }
    EXPECT_DOUBLE_EQ(j["delta"]["accuracy"]["grossShare"].get<double>(), 4.0 / 200.0);
}

std::string readText(const std::filesystem::path& f) {
    std::ifstream in(f);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

sweep::Manifest manifestFor(const std::vector<sweep::PointResult>& points, const std::filesystem::path& dir) {
    sweep::Manifest m;
    m.sweep = "t";
    m.scene = "builtin:box-over-plane";
    m.presetDir = dir;
    m.width = 64, m.height = 36;
    m.axisFields = {"cascades.count"};
    m.axisValues = {{}};
    for (const auto& p : points) m.pointIds.push_back(p.id), m.axisValues[0].push_back(p.id);
    m.baseValues = {m.axisValues[0][0]};
    return m;
}

std::vector<sweep::PointResult> pointsOf(const FigureTable& table) {
    Settings s;
    s.scene = "builtin:box-over-plane";
    std::vector<sweep::PointResult> points;
    for (int i = 1; i <= 3; ++i) {
        auto m = known();
        m.accuracy.all.falseLightGross = std::size_t(10 * i);
        m.cost->gpuMainMs = 10.0 - i;  // the better, the cheaper: all three are on the front
        m.cost->model->mainMs = 10.0 - i;
        m.cost->model->totalMs = 3.0 + 0.5 + m.cost->model->mainMs;
        points.push_back({std::to_string(i), "p" + std::to_string(i), false, {std::to_string(i)}, toOrderedJson(s),
                          sweep::figuresOf(m, table)});
    }
    return points;
}

TEST(FigureTableTest, SweepResultsListEveryRowInTableOrderWithRawValues) {
    test::TempDir dir;
    const auto points = pointsOf(metrics::figureTable());
    sweep::writeReport(dir.path(), manifestFor(points, dir.path()), points, {});
    const std::string csv = readText(dir.path() / "results.csv");
    std::string header = "id,kind,label,cascades.count";
    for (const FigureRow* r : metrics::figuresShown(metrics::InSweep)) header += "," + r->key;
    EXPECT_EQ(csv.substr(0, csv.find('\n')), header);
    const OJson results = OJson::parse(readText(dir.path() / "results.json"));
    EXPECT_EQ(results["points"][0]["version"], sweep::kSweepResultsVersion);
    EXPECT_DOUBLE_EQ(results["points"][0]["figures"]["accuracy.misclassified"].get<double>(), 21.0 / 200.0);
    EXPECT_TRUE(results["points"][0]["figures"]["flicker.flipRate"].is_null());
    const OJson front = OJson::parse(readText(dir.path() / "front.json"));
    ASSERT_EQ(front.size(), 3u);
    EXPECT_EQ(front[0]["cost.modelMs"], 3.0 + 0.5 + 9.0) << "the front's cost is the modelled one by default";
}

TEST(FigureTableTest, DocsListEveryRow) {
    const std::string md = metrics::figuresMarkdown();
    for (const FigureRow& r : metrics::figureTable()) {
        std::string label;
        for (const char c : r.label) label += c == '|' ? std::string("\\|") : std::string(1, c);
        EXPECT_NE(md.find("| `" + r.key + "` | " + label + " |"), std::string::npos) << r.key;
        // Every table line has its 8 unescaped bars: a "|" in a description must not split a cell.
        const std::size_t at = md.find("| `" + r.key + "` |");
        const std::string line = md.substr(at, md.find('\n', at) - at);
        int bars = 0;
        for (std::size_t i = 0; i < line.size(); ++i) bars += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
        EXPECT_EQ(bars, 8) << line;
        if (!r.choice.empty()) EXPECT_NE(md.find("`" + r.choice + "`"), std::string::npos) << r.choice;
    }
}

// A row appended to the table, shown everywhere: every output lists it with no other edit.
TEST(FigureTableTest, AFigureAddedToTheTableShowsUpEverywhere) {
    FigureTable table = metrics::figureTable();
    table.push_back({"synthetic.answer", "the answer", FigureUnit::Count, metrics::Better::Lower,
                     [](const metrics::PresetMeasurement& m) -> std::optional<double> {
                         return double(m.accuracy.all.receivers) / 5.0;  // 40 for known()
                     },
                     "answer", "the answer (count)", "A figure only this test knows.",
                     metrics::InMetricsJson | metrics::InCompare | metrics::InSweep | metrics::ErrorChoice |
                         metrics::InEditorAccuracy | metrics::InEditorSweep});
    const auto m = known();
    EXPECT_EQ(metrics::toJson(m, "p", table)["synthetic"]["answer"], 40);

    const auto figures = metrics::compareFigures(m, m, table);
    const OJson j = metrics::compareJson({"a", "b", "a.json", "b.json"}, figures, m, std::nullopt);
    EXPECT_EQ(j["a"]["synthetic"]["answer"], 40);
    EXPECT_EQ(j["delta"]["synthetic"]["answer"], 0);
    EXPECT_NE(metrics::compareTable({"a", "b", "a.json", "b.json"}, figures, std::nullopt).find("\nthe answer "),
              std::string::npos);

    EXPECT_EQ(metrics::readFigures(m, metrics::InEditorAccuracy, table).back().value, 40.0);
    EXPECT_EQ(metrics::readFigures(m, metrics::InEditorSweep, table).back().row->key, "synthetic.answer");
    EXPECT_EQ(metrics::choicesOf(metrics::ErrorChoice, table).back(), "answer");
    EXPECT_NE(metrics::figuresMarkdown(table).find("| `synthetic.answer` | the answer |"), std::string::npos);

    test::TempDir dir;
    const auto points = pointsOf(table);
    EXPECT_EQ(points[0].figure("synthetic.answer"), 40.0);
    sweep::writeReport(dir.path(), manifestFor(points, dir.path()), points, {"answer", "measured"}, table);
    const std::string csv = readText(dir.path() / "results.csv");
    EXPECT_TRUE(csv.substr(0, csv.find('\n')).ends_with(",synthetic.answer"));
    EXPECT_EQ(OJson::parse(readText(dir.path() / "front.json"))[0]["synthetic.answer"], 40);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "axis-cascades.count-synthetic.answer.png"));
}

TEST(FigureTableTest, AResultsFolderOfTheOldKeysIsRefusedSayingWhy) {
    const OJson old = {{"version", 1}, {"sweep", "s"}, {"fingerprint", "f"}};
    try {
        sweep::manifestFromJson(old, "old/sweep.json");
        ADD_FAILURE() << "an old manifest was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("old/sweep.json: written with sweep results version 1"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("another --out"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sweep::pointFromJson(OJson{{"version", 1}, {"id", "x"}}, "old/points/x.json"), std::runtime_error);
}

}  // namespace
}  // namespace st
