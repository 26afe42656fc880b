// `shadowtune compare` without GL: figures and deltas, the shadow diff, the table's formats, the
// composed images (cairo text only ever under the pictures).
#include "app/images/compare_images.h"
#include "metrics/compare.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <cstring>

namespace st {
namespace {
using metrics::CompareFigure;
using metrics::DiffClass;
using metrics::FigureUnit;

metrics::PresetMeasurement measurement(std::size_t falseShadow, double gpuShadowMs) {
    metrics::PresetMeasurement m;
    m.samples = test::floorSamples(4, 4);
    m.accuracy.all.receivers = 100;
    m.accuracy.all.falseShadowEdge = falseShadow;
    m.accuracy.all.falseLightGross = 1;
    m.accuracy.all.filteredAbsErrorSum = 2.5;
    m.density.all = {16, 1.0, 2.0, 3.0, 4.0, 0.5, 0.1};
    m.cost = metrics::CostReport{};
    m.cost->gpuShadowMs = gpuShadowMs;
    m.cost->shadowMapBytes = 4u << 20;
    m.cost->triangles = 1200;
    m.cost->model = metrics::ModelledCost{{gpuShadowMs}, gpuShadowMs, 2.0, 0.0, 0.0, gpuShadowMs + 2.0};
    return m;
}

const CompareFigure& figure(const std::vector<CompareFigure>& figures, const std::string& key) {
    for (const CompareFigure& f : figures)
        if (f.key == key) return f;
    throw std::runtime_error("no figure " + key);
}

TEST(CompareTest, SameMeasurementHasEveryDeltaExactlyZero) {
    const auto m = measurement(3, 1.5);
    for (const CompareFigure& f : metrics::compareFigures(m, m)) {
        if (f.key.rfind("flicker.", 0) == 0) {  // flipRate, alternatingPixels
            EXPECT_FALSE(f.delta()) << "no path, no flicker figure: " << f.key;
            continue;
        }
        ASSERT_TRUE(f.delta()) << f.key;
        EXPECT_EQ(*f.delta(), 0.0) << f.key;
    }
}

TEST(CompareTest, DeltasAreBMinusA) {
    const auto figures = metrics::compareFigures(measurement(3, 1.5), measurement(8, 1.0));
    EXPECT_DOUBLE_EQ(*figure(figures, "accuracy.misclassified").delta(), 0.05);
    EXPECT_DOUBLE_EQ(*figure(figures, "accuracy.falseShadow").delta(), 0.05);
    EXPECT_DOUBLE_EQ(*figure(figures, "accuracy.edgeBand").delta(), 0.05);
    EXPECT_EQ(*figure(figures, "accuracy.grossShare").delta(), 0.0);
    EXPECT_DOUBLE_EQ(*figure(figures, "cost.gpuShadowMs").delta(), -0.5);
    EXPECT_DOUBLE_EQ(*figure(figures, "accuracy.misclassified").a, 0.04);
}

TEST(CompareTest, JsonHoldsBothSidesAndDeltasAtTheKeysPaths) {
    const auto a = measurement(3, 1.5), b = measurement(8, 1.0);
    const auto j = metrics::compareJson({"a", "b", "a.json", "b.json"}, metrics::compareFigures(a, b), a, std::nullopt);
    EXPECT_DOUBLE_EQ(j["delta"]["accuracy"]["misclassified"].get<double>(), 0.05);
    EXPECT_DOUBLE_EQ(j["b"]["accuracy"]["misclassified"].get<double>(), 0.09);
    EXPECT_EQ(j["a"]["cost"]["shadowMapBytes"].get<long long>(), 4 << 20);
    EXPECT_TRUE(j["delta"]["flicker"]["flipRate"].is_null());
    EXPECT_TRUE(j["shadowDiff"].is_null());
    EXPECT_EQ(j["a"]["preset"], "a");
}

TEST(CompareTest, TableFormatsCarryUnitsAndSigns) {
    EXPECT_EQ(metrics::formatValue(FigureUnit::Share, 0.01234), "1.234 %");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Share, 0.005), "+0.500 pp");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Ms, -1.0), "-1.00 ms");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Bytes, 0.0), "±0 MiB");
    EXPECT_EQ(metrics::formatValue(FigureUnit::Bytes, double(16 << 20)), "16.0 MiB");
    EXPECT_EQ(metrics::formatDelta(FigureUnit::Count, 12.0), "+12");
    EXPECT_EQ(metrics::formatValue(FigureUnit::Ms, std::nullopt), "-");
}

TEST(CompareTest, ShadowDiffSortsPixelsIntoFourClassesAndUnscored) {
    MeasureSamples a = test::floorSamples(4, 1), b = test::floorSamples(4, 1);
    test::setMap(a, 1, 0, 0.0f, 0.0f);  // only A shadows
    test::setMap(b, 2, 0, 0.0f, 0.0f);  // only B shadows
    test::setMap(a, 3, 0, 0.0f, 0.0f);  // both
    test::setMap(b, 3, 0, 0.0f, 0.0f);
    a.normal[0].w = -1.0f;  // pixel 0 faces away in A: not scored
    const metrics::ShadowDiff d = metrics::shadowDiff(a, b);
    EXPECT_EQ(d.classes, (std::vector{DiffClass::Unscored, DiffClass::OnlyA, DiffClass::OnlyB, DiffClass::Both}));
    EXPECT_EQ(d.scored(), 3u);
    EXPECT_EQ(d.onlyA + d.onlyB + d.both + d.neither + d.unscored, 4u);
    EXPECT_THROW(metrics::shadowDiff(a, test::floorSamples(3, 1)), std::invalid_argument);
}

Rgba8Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Rgba8Image img{w, h, std::vector<std::uint8_t>(std::size_t(w) * std::size_t(h) * 4, 255)};
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) img.pixels[i] = r, img.pixels[i + 1] = g, img.pixels[i + 2] = b;
    // a gradient, so a shifted or mirrored copy would not pass
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) img.pixels[i + 1] = std::uint8_t((i / 4) % 251);
    return img;
}

const std::uint8_t* px(const Rgba8Image& img, int x, int y) {
    return &img.pixels[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
}

TEST(CompareImagesTest, SplitKeepsEachHalfOfItsPictureOutsideTheDivider) {
    const Rgba8Image a = solid(160, 90, 200, 0, 10), b = solid(160, 90, 10, 0, 200);
    const app::Strip la{{"A: left", std::nullopt, true}}, lb{{"B: right", std::nullopt, true}};
    const Rgba8Image s = app::splitImage(a, b, la, lb);
    const app::SplitLayout l = app::splitLayout(a.width, a.height);
    ASSERT_EQ(s.width, 160);
    ASSERT_GT(s.height, 90) << "the labels sit below the picture";
    int checked = 0;
    for (int y = 0; y < l.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            if (x >= l.x0 && x < l.x1) continue;
            const Rgba8Image& src = x < l.x0 ? a : b;
            ASSERT_EQ(std::memcmp(px(s, x, y), px(src, x, y), 4), 0) << x << "," << y;
            ++checked;
        }
    EXPECT_EQ(checked, 90 * (160 - 2));
    EXPECT_THROW(app::splitImage(a, solid(80, 90, 0, 0, 0), la, lb), std::invalid_argument);
}

TEST(CompareImagesTest, StripsDrawWhiteTextOnADarkBand) {
    const Rgba8Image a = solid(320, 180, 90, 90, 90);
    const app::Strip label{{"A: default", std::nullopt, true}, {"misclassified 1.234 %"}, {"GPU 1.00 + 2.00 ms"}};
    const Rgba8Image s = app::sideBySideImage(a, a, label, label);
    EXPECT_EQ(s.width, 2 * 320 + 4);
    int white = 0, dark = 0;
    for (int y = 180; y < s.height; ++y)
        for (int x = 0; x < 320; ++x) {
            const std::uint8_t* p = px(s, x, y);
            white += p[0] > 240 && p[1] > 240 && p[2] > 240;
            dark += p[0] == app::kStripBackground[0] && p[2] == app::kStripBackground[2];
            ASSERT_EQ(p[3], 255);
        }
    EXPECT_GT(white, 100) << "text is drawn";
    EXPECT_GT(dark, white) << "on a dark band";
}

TEST(CompareImagesTest, ShadowDiffShowsOnlyTheClassesPresent) {
    MeasureSamples a = test::floorSamples(64, 32), b = test::floorSamples(64, 32);
    const auto count = [](const Rgba8Image& img, int rows, const app::Rgb8& c) {
        int n = 0;
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < img.width; ++x) n += std::memcmp(px(img, x, y), c.data(), 3) == 0;
        return n;
    };
    const app::Rgb8 onlyA = app::diffColour(DiffClass::OnlyA), onlyB = app::diffColour(DiffClass::OnlyB);
    const Rgba8Image same = app::shadowDiffImage(metrics::shadowDiff(a, b), "a", "b");
    EXPECT_EQ(count(same, 32, onlyA) + count(same, 32, onlyB), 0);
    EXPECT_GT(count(same, same.height, onlyA), 0) << "the legend shows the swatch";
    test::setMap(b, 5, 5, 0.0f, 0.0f);
    EXPECT_EQ(count(app::shadowDiffImage(metrics::shadowDiff(a, b), "a", "b"), 32, onlyB), 1);
}

// cairo's and fontconfig's caches go before LeakSanitizer looks (scripts/asan.sh).
class ReleaseTextCaches : public ::testing::Environment {
public:
    void TearDown() override { app::releaseTextCaches(); }
};
const auto* const kRelease = ::testing::AddGlobalTestEnvironment(new ReleaseTextCaches);

}  // namespace
}  // namespace st
