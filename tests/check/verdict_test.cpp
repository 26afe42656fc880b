// Figure rules, image differences and verdicts on cases whose answers are worked out by hand.
#include "check/check_run.h"
#include "check/figure_check.h"
#include "check/image_diff.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::check;

namespace {
FigureTolerance rule(const std::string& figure, FigureRule r, double limit) { return {&figureNamed(figure), r, limit}; }

Rgba8Image flat(int w, int h, std::uint8_t v) {
    return {w, h, std::vector<std::uint8_t>(std::size_t(w) * std::size_t(h) * 4, v)};
}
}  // namespace

TEST(FigureCheckTest, NamesResolveToTheTablesRows) {
    EXPECT_EQ(figureNamed("misclassified").key, "accuracy.misclassified");
    EXPECT_EQ(figureNamed("flicker").key, "flicker.flipRate");
    EXPECT_EQ(figureNamed("softFilteredError").key, "soft.filteredError");
    EXPECT_EQ(figureNamed("soft.penumbraWidth.absErrorPx").key, "soft.penumbraWidth.absErrorPx");
    EXPECT_THROW(figureNamed("filteredError"), std::invalid_argument);  // accuracy. or soft.
}

TEST(FigureCheckTest, PercentagePointsOfAShare) {
    const FigureTolerance t = rule("misclassified", FigureRule::WorseByAtMostPp, 0.05);
    // 1.00 % -> 1.04 % is 0.04 pp worse: within; 1.06 % is 0.06 pp: not; better is always within.
    EXPECT_TRUE(checkFigure(t, 0.0100, 0.0104).pass);
    const FigureVerdict bad = checkFigure(t, 0.0100, 0.0106);
    EXPECT_FALSE(bad.pass);
    EXPECT_NE(bad.message.find("+0.060 pp"), std::string::npos) << bad.message;
    EXPECT_NE(bad.message.find("0.05 pp"), std::string::npos) << bad.message;
    EXPECT_TRUE(checkFigure(t, 0.0100, 0.0001).pass);
}

TEST(FigureCheckTest, FactorMaxAndMissingValues) {
    const FigureTolerance f = rule("softFilteredError", FigureRule::WorseByAtMostFactor, 1.1);
    EXPECT_TRUE(checkFigure(f, 0.100, 0.109).pass);
    EXPECT_FALSE(checkFigure(f, 0.100, 0.111).pass);
    const FigureTolerance m = rule("flicker", FigureRule::Max, 0.0);
    EXPECT_TRUE(checkFigure(m, 0.2, 0.0).pass);      // a bound ignores the golden
    EXPECT_FALSE(checkFigure(m, 0.0, 1e-6).pass);
    EXPECT_TRUE(checkFigure(m, std::nullopt, std::nullopt).pass);    // no path in either run
    EXPECT_FALSE(checkFigure(m, 0.0, std::nullopt).pass);            // the path went away
    EXPECT_FALSE(checkFigure(f, std::nullopt, 0.1).pass);            // nothing to compare with
}

TEST(ImageDiffTest, CountsPixelsOverTheChannelTolerance) {
    Rgba8Image golden = flat(10, 10, 100), actual = golden;
    actual.pixels[0] = 106;            // pixel 0: 6 over 5 -> fails
    actual.pixels[4 * 7 + 2] = 105;    // pixel 7: exactly 5 -> passes
    ImageTolerance tol;                // 5/255, 0.1 %
    ImageDiff d = diffImages(actual, golden, tol);
    EXPECT_EQ(d.maxChannelDiff, 6);
    EXPECT_EQ(d.failingPixels, 1u);
    EXPECT_DOUBLE_EQ(d.failingShare, 0.01);
    EXPECT_FALSE(d.pass);              // 1 % > 0.1 %
    tol.maxFailingShare = 0.01;
    EXPECT_TRUE(diffImages(actual, golden, tol).pass);
    EXPECT_FALSE(diffImages(flat(5, 5, 0), golden, tol).sizeMatches);
    const Rgba8Image pic = diffPicture(actual, golden, ImageTolerance{});
    EXPECT_EQ(pic.pixels[0], 255);     // red where it fails
    EXPECT_EQ(pic.pixels[1], 0);
    EXPECT_EQ(pic.pixels[4 * 7], 40);  // 5 x 8 grey where it passes
}

TEST(VerdictTest, AnAccuracyRegressionFailsWithinTheImageTolerance) {
    SuiteEntry e;
    e.name = "p";
    e.figures = {rule("misclassified", FigureRule::WorseByAtMostPp, 0.05)};
    Actual a{flat(8, 8, 50), {{"accuracy", {{"misclassified", 0.02}}}}, {"llvmpipe", "0.1", "c", "h", 8, 8}};
    Golden g{"dir", a.meta, a.image, {{"accuracy", {{"misclassified", 0.01}}}}};
    PresetResult r = judge(e, a, g);
    EXPECT_TRUE(r.image->pass);
    EXPECT_EQ(r.status, Status::Failed);
    EXPECT_NE(r.message.find("misclassified"), std::string::npos);
    EXPECT_EQ(r.figures.front().row->key, "accuracy.misclassified");  // the failing check first
    g.figures = a.figures;
    EXPECT_EQ(judge(e, a, g).status, Status::Pass);
    g.meta.renderer = "other";
    EXPECT_EQ(judge(e, a, g).status, Status::RendererMismatch);
    e.onRendererMismatch = OnRendererMismatch::Compare;
    r = judge(e, a, g);
    EXPECT_EQ(r.status, Status::Pass);
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_EQ(judge(e, a, std::nullopt).status, Status::GoldenMissing);
    EXPECT_EQ(exitCodeOf({judge(e, a, g)}), 0);
    EXPECT_EQ(exitCodeOf({judge(e, a, g), judge(e, a, std::nullopt)}), 1);
}

TEST(VerdictTest, UpdateSaysWhatChanged) {
    SuiteEntry e;
    e.name = "p";
    Actual a{flat(8, 8, 50), {{"accuracy", {{"misclassified", 0.02}}}}, {"llvmpipe", "0.1", "c", "h", 8, 8}};
    Golden g{"dir", a.meta, a.image, a.figures};
    EXPECT_EQ(updateVerdict(e, a, g).status, Status::Unchanged);
    EXPECT_EQ(updateVerdict(e, a, std::nullopt).status, Status::New);
    g.figures["accuracy"]["misclassified"] = 0.01;
    const PresetResult r = updateVerdict(e, a, g);
    EXPECT_EQ(r.status, Status::Updated);
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_EQ(r.notes[0], "misclassified 1.000 % -> 2.000 % (+1.000 pp)");
}
