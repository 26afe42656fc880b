// The charts (report/charts.h): files of the right size and kind, texts in the SVG, failures that
// name the file and leave nothing behind, and PLplot's global state not leaking between charts.
#include "report/charts.h"

#include "renderer/image/image_io.h"
#include "tests/report/chart_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <thread>

namespace {
namespace fs = std::filesystem;
using namespace st::report;

ScatterChart sampleScatter(std::size_t tableRows = 0) {
    ScatterChart c;
    c.title = "yard 640x360: misclassified vs GPU time";
    c.subtitle = "llvmpipe #1";
    c.xLabel = "GPU time, shadow + main (ms)";
    c.yLabel = "misclassified (% of sun-facing pixels)";
    c.logY = true;
    for (int i = 0; i < 20; ++i) c.points.push_back({1.0 + i, 10.0 / (1.0 + i) + (i % 3), "", i % 3 == 0, false});
    c.points.push_back({4.5, 3.0, "default", false, true});
    c.tableHeader = {"GPU ms", "misclassified %"};
    for (std::size_t r = 0; r < tableRows; ++r) c.tableRows.push_back({std::to_string(r), "1.5"});
    return c;
}

LineChart sampleLines() {
    LineChart l;
    l.title = "misclassified by fit";
    l.xLabel = "fit mode";
    l.yLabel = "misclassified (%)";
    l.xTickLabels = {"cascade", "scene", "sphere"};
    l.series = {{"1024 px", {0, 1, 2}, {3, 2, 2.5}}, {"2048 px", {0, 1, 2}, {1.5, 1.0, 1.2}}};
    return l;
}

bool moreThanOneColour(const st::Rgba8Image& img) {
    for (std::size_t i = 4; i < img.pixels.size(); i += 4)
        if (!std::equal(img.pixels.begin() + long(i), img.pixels.begin() + long(i) + 3, img.pixels.begin())) return true;
    return false;
}

std::string bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST(ScatterChartTest, WritesAPngOfTheDefaultSizeThatIsNotBlank) {
    fs::path dir = st::test::freshFolder("scatter-png");
    writeScatterChart(sampleScatter(), dir / "chart.png", {});
    st::Rgba8Image img = st::readImage(dir / "chart.png");
    EXPECT_EQ(img.width, 1200);
    EXPECT_EQ(img.height, 900);
    EXPECT_TRUE(moreThanOneColour(img));
    EXPECT_FALSE(fs::exists(dir / "chart.svg"));
    EXPECT_FALSE(st::test::hasTempFiles(dir));
}

TEST(ScatterChartTest, ThePageGrowsWithTheTableUpToTheRowCap) {
    fs::path dir = st::test::freshFolder("scatter-rows");
    // One file per size: st::readImage goes through OIIO's shared ImageCache, which keeps the
    // header of a path it has read, so a rewritten file would be read with the old size.
    auto heightWith = [&](std::size_t rows) {
        fs::path png = dir / ("rows" + std::to_string(rows) + ".png");
        writeScatterChart(sampleScatter(rows), png, {});
        return st::readImage(png).height;
    };
    int two = heightWith(2), ten = heightWith(10), thirty = heightWith(30), forty = heightWith(40);
    EXPECT_GT(two, 900);
    EXPECT_GT(ten, two);
    EXPECT_GT(thirty, ten);
    EXPECT_EQ(thirty, forty) << "25 rows and a '... N more' line at most";
}

TEST(ScatterChartTest, ExplicitSizeIsKept) {
    fs::path dir = st::test::freshFolder("scatter-size");
    ScatterChart c = sampleScatter(3);
    c.width = 640, c.height = 500;
    writeScatterChart(c, dir / "chart.png", {});
    st::Rgba8Image img = st::readImage(dir / "chart.png");
    EXPECT_EQ(img.width, 640);
    EXPECT_EQ(img.height, 500);
}

TEST(ScatterChartTest, SvgCarriesTitleAxisLabelsLegendAndReferenceLabelsAsText) {
    fs::path dir = st::test::freshFolder("scatter-svg");
    writeScatterChart(sampleScatter(2), {}, dir / "chart.svg");
    std::string svg = st::test::svgText(dir / "chart.svg");
    for (const char* text : {"yard 640x360: misclassified vs GPU time", "llvmpipe #1", "GPU time, shadow + main (ms)",
                             "misclassified (% of sun-facing pixels)", "all points", "Pareto front", "reference presets",
                             "default", "misclassified %"})
        EXPECT_NE(svg.find(text), std::string::npos) << text;
    EXPECT_NE(svg.find("width=\"1200\""), std::string::npos) << "the SVG is sized in pixels like the PNG";
    EXPECT_NE(svg.find("font-family=\"'DejaVu Sans Mono', monospace\""), std::string::npos) << "the table is monospace";
    EXPECT_NE(svg.find("font-family=\"'DejaVu Sans', sans-serif\""), std::string::npos) << "the rest names its family";
    EXPECT_EQ(svg.find("mono-space"), std::string::npos) << "PLplot's name no viewer knows";
}

TEST(ScatterChartTest, ValuesALogAxisCannotShowAreClampedAndSaidSo) {
    fs::path dir = st::test::freshFolder("scatter-clamp");
    ScatterChart c = sampleScatter();
    c.logX = true;
    c.points.push_back({0.0, 0.0, "zero", true, true});
    c.points.push_back({-1.0, 2.0, "", false, false});
    c.points.push_back({std::numeric_limits<double>::quiet_NaN(), 1.0, "", false, false});
    writeScatterChart(c, dir / "chart.png", dir / "chart.svg");
    std::string svg = st::test::svgText(dir / "chart.svg");
    EXPECT_NE(svg.find("2 values of x ≤ 0 drawn at"), std::string::npos);
    EXPECT_NE(svg.find("1 value of y ≤ 0 drawn at"), std::string::npos);
    EXPECT_NE(svg.find("1 point without a finite value not drawn"), std::string::npos);
    EXPECT_TRUE(moreThanOneColour(st::readImage(dir / "chart.png")));
}

TEST(ScatterChartTest, EmptyChartStillHasAxesAndTitle) {
    fs::path dir = st::test::freshFolder("scatter-empty");
    ScatterChart c;
    c.title = "nothing measured";
    c.logX = c.logY = true;
    writeScatterChart(c, dir / "chart.png", dir / "chart.svg");
    EXPECT_NE(st::test::svgText(dir / "chart.svg").find("nothing measured"), std::string::npos);
}

TEST(ChartFileTest, MissingFolderThrowsNamingTheFileAndLeavesNoTempFile) {
    fs::path dir = st::test::freshFolder("missing");
    fs::path png = dir / "no-such-folder" / "chart.png";
    try {
        writeScatterChart(sampleScatter(), png, {});
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(png.string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "no-such-folder"));
    EXPECT_FALSE(st::test::hasTempFiles(dir));
}

// Root may write anywhere, so "unwritable" is a folder path through a regular file (ENOTDIR).
TEST(ChartFileTest, UnwritableFolderThrowsNamingTheFileAndTheNextChartStillWorks) {
    fs::path dir = st::test::freshFolder("unwritable");
    std::ofstream(dir / "file") << "x";
    fs::path svg = dir / "file" / "chart.svg";
    try {
        writeLineChart(sampleLines(), {}, svg);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(svg.string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(st::test::hasTempFiles(dir));
    writeLineChart(sampleLines(), dir / "after.png", dir / "after.svg");
    EXPECT_TRUE(moreThanOneColour(st::readImage(dir / "after.png")));
}

// PLplot keeps global state: a chart drawn after another, or the SVG after the PNG, must not
// inherit anything (axis, colours, font, stream) from it.
TEST(ChartFileTest, ChartsWrittenOneAfterAnotherDoNotShareState) {
    fs::path dir = st::test::freshFolder("sequence");
    writeScatterChart(sampleScatter(3), dir / "first.png", dir / "first.svg");
    writeLineChart(sampleLines(), dir / "line.png", dir / "line.svg");
    writeScatterChart(sampleScatter(3), dir / "again.png", dir / "again.svg");
    EXPECT_EQ(bytes(dir / "first.png"), bytes(dir / "again.png"));
    EXPECT_EQ(bytes(dir / "first.svg"), bytes(dir / "again.svg"));
}

TEST(ChartFileTest, ChartsFromSeveralThreadsAreSerialised) {
    fs::path dir = st::test::freshFolder("threads");
    writeLineChart(sampleLines(), dir / "reference.png", {});
    std::vector<std::thread> threads;
    for (int t = 0; t < 3; ++t)
        threads.emplace_back([&dir, t] { writeLineChart(sampleLines(), dir / ("t" + std::to_string(t) + ".png"), {}); });
    for (std::thread& t : threads) t.join();
    for (int t = 0; t < 3; ++t) EXPECT_EQ(bytes(dir / ("t" + std::to_string(t) + ".png")), bytes(dir / "reference.png"));
}

TEST(LineChartTest, CategoryLabelsSeriesNamesAndSizeInBothFiles) {
    fs::path dir = st::test::freshFolder("line");
    LineChart l = sampleLines();
    l.logY = true;
    l.series[0].y[1] = std::numeric_limits<double>::quiet_NaN();  // breaks the line, no crash
    writeLineChart(l, dir / "line.png", dir / "line.svg");
    st::Rgba8Image img = st::readImage(dir / "line.png");
    EXPECT_EQ(img.width, 1200);
    EXPECT_EQ(img.height, 900);
    EXPECT_TRUE(moreThanOneColour(img));
    std::string svg = st::test::svgText(dir / "line.svg");
    for (const char* text : {"misclassified by fit", "fit mode", "misclassified (%)", "cascade", "scene", "sphere",
                             "1024 px", "2048 px"})
        EXPECT_NE(svg.find(text), std::string::npos) << text;
}

}  // namespace
