// One small fixed scatter chart against tests/golden/report/small_scatter.png.
// ST_UPDATE_GOLDENS=1 rewrites the golden (look at it before committing).
#include "report/charts.h"

#include "renderer/image/image_io.h"
#include "tests/report/chart_files.h"
#include "tests/support/image_compare.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace {
namespace fs = std::filesystem;
using namespace st::report;

ScatterChart smallScatter() {
    ScatterChart c;
    c.title = "golden: error vs time";
    c.subtitle = "fixed data";
    c.xLabel = "GPU time (ms)";
    c.yLabel = "misclassified (%)";
    c.logY = true;
    c.width = 600;
    c.points = {{1, 8, "", true, false},  {2, 3, "", true, false},  {4, 1, "", true, false},  {3, 5, "", false, false},
                {5, 4, "", false, false}, {6, 2, "", false, false}, {2.5, 6, "preset-a", false, true},
                {5, 1.5, "preset-b", false, true}};
    c.tableHeader = {"GPU ms", "misclassified %"};
    c.tableRows = {{"1.00", "8.00"}, {"2.00", "3.00"}, {"4.00", "1.00"}};
    return c;
}

TEST(ChartGoldenTest, SmallScatterMatchesTheGolden) {
    fs::path golden = fs::path(ST_REPORT_GOLDEN_DIR) / "small_scatter.png";
    fs::path dir = st::test::freshFolder("golden");
    writeScatterChart(smallScatter(), dir / "small_scatter.png", {});
    st::Rgba8Image actual = st::readImage(dir / "small_scatter.png");
    if (std::getenv("ST_UPDATE_GOLDENS")) {
        fs::create_directories(golden.parent_path());
        st::writeImageAtomic(golden, actual);
        GTEST_SKIP() << "golden rewritten: " << golden;
    }
    // Bit-identical between runs on this machine (Debian 12's cairo 1.16, pango 1.50, DejaVu
    // fonts). The slack is for other builds of those, which move antialiased glyph edges by a few
    // levels: a pixel fails above 24/255 in a channel, the image above 0.2 % failing pixels
    // (about 620). A moved axis, plot area, marker set or table fails (shifting the whole page
    // by one pixel puts 7 % of the pixels out); a changed letter in one label (about 25
    // pixels) does not: the SVG tests check the texts.
    st::test::Tolerance tol{24, 0.002};
    st::test::CompareResult r = st::test::compareImages(actual, st::readImage(golden), tol);
    if (!r.pass) {
        fs::create_directories(ST_ARTIFACT_DIR);
        st::writeImageAtomic(fs::path(ST_ARTIFACT_DIR) / "report.small_scatter.actual.png", actual);
        st::writeImageAtomic(fs::path(ST_ARTIFACT_DIR) / "report.small_scatter.diff.png",
                             st::test::diffImage(actual, st::readImage(golden), tol));
    }
    EXPECT_TRUE(r.pass) << r.summary() << " (artifacts in " << ST_ARTIFACT_DIR << ")";
}

}  // namespace
