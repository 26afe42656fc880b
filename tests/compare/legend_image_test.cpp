// The legends of errors.png and artifacts.png: every colour the image uses is in its legend with
// the image's pixel count of it, and withLegend() keeps the image and draws the strip under it.
#include "app/images/label_strip.h"
#include "app/images/legend_image.h"
#include "metrics/metric_images.h"
#include "metrics/soft_accuracy.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>

namespace st {
namespace {

using Colour = std::array<std::uint8_t, 3>;

std::map<Colour, std::size_t> colours(const Rgba8Image& img, int rows) {
    std::map<Colour, std::size_t> out;
    for (std::size_t i = 0; i < std::size_t(img.width) * std::size_t(rows); ++i)
        ++out[{img.pixels[4 * i], img.pixels[4 * i + 1], img.pixels[4 * i + 2]}];
    return out;
}

void expectLegendCovers(const Rgba8Image& img, const std::vector<metrics::LegendEntry>& legend) {
    for (const auto& [c, n] : colours(img, img.height)) {
        bool found = false;
        for (const metrics::LegendEntry& e : legend) {
            if (e.colour != c) continue;
            found = true;
            EXPECT_EQ(e.pixels, n) << e.name;
        }
        EXPECT_TRUE(found) << "colour " << int(c[0]) << "," << int(c[1]) << "," << int(c[2]) << " is in no legend entry";
    }
}

// An umbra with light bleeding through its middle, acne on the lit floor, a lost shadow.
struct Case {
    MeasureSamples s = test::floorSamples(48, 32);
    metrics::SoftTruth t{std::vector<float>(48 * 32, 1.0f),
                         std::vector<float>(48 * 32, std::numeric_limits<float>::infinity())};
    metrics::SoftAccuracyReport r;
    Case() {
        for (int y = 4; y < 28; ++y)
            for (int x = 4; x < 24; ++x) {
                t.visible[std::size_t(y) * 48 + std::size_t(x)] = 0.0f;
                t.blocker[std::size_t(y) * 48 + std::size_t(x)] = 5.0f;
                const bool hole = x >= 12 && x < 16 && y >= 14 && y < 18;
                test::setMap(s, x, y, hole ? 1.0f : 0.0f, hole ? 1.0f : 0.0f);
            }
        for (int x = 30; x < 34; ++x) t.visible[std::size_t(2) * 48 + std::size_t(x)] = 0.0f;  // lost
        test::setMap(s, 40, 20, 1.0f, 0.2f);                                                  // acne
        s.position[std::size_t(31) * 48 + 47].w = 0.0f;                                      // no surface
        r = metrics::scoreSoftAccuracy(s, t, {1.0f});
    }
};

TEST(LegendImageTest, ArtifactLegendCoversEveryColourWithItsCount) {
    const Case c;
    EXPECT_EQ(c.r.all.lightBleeding, 16u);
    EXPECT_EQ(c.r.all.acne, 1u);
    EXPECT_EQ(c.r.all.missingCaster, 4u);
    const Rgba8Image img = metrics::artifactImage(c.s, c.t, c.r);
    const std::vector<metrics::LegendEntry> legend = metrics::artifactLegend(c.t, c.r);
    expectLegendCovers(img, legend);
    std::map<std::string, std::size_t> byName;
    for (const metrics::LegendEntry& e : legend) byName[e.name] = e.pixels;
    EXPECT_EQ(byName["light bleeding"], 16u);
    EXPECT_EQ(byName["acne"], 1u);
    EXPECT_EQ(byName["missing caster"], 4u);
    EXPECT_EQ(byName["not scored"], 1u);
    EXPECT_EQ(byName["correct, umbra"], 20u * 24u - 16u);
}

TEST(LegendImageTest, ErrorLegendCoversEveryColourWithItsCount) {
    metrics::AccuracyReport a;
    a.classes = {metrics::PixelClass::CorrectLit, metrics::PixelClass::FalseShadowGross,
                 metrics::PixelClass::FalseLightEdge, metrics::PixelClass::CorrectLit,
                 metrics::PixelClass::NoSurface, metrics::PixelClass::FacingAway};
    const Rgba8Image img = metrics::errorImage(a, 3, 2);
    expectLegendCovers(img, metrics::errorLegend(a));
}

TEST(LegendImageTest, WithLegendKeepsTheImageAndDrawsTheStripUnderIt) {
    const Case c;
    const Rgba8Image img = metrics::artifactImage(c.s, c.t, c.r);
    const Rgba8Image out = app::withLegend(img, "artifacts", metrics::artifactLegend(c.t, c.r));
    ASSERT_EQ(out.width, img.width);
    ASSERT_GT(out.height, img.height + 10);
    EXPECT_TRUE(std::equal(img.pixels.begin(), img.pixels.end(), out.pixels.begin())) << "the image is untouched";
    const std::map<Colour, std::size_t> strip = [&] {
        Rgba8Image band{out.width, out.height - img.height,
                        std::vector<std::uint8_t>(out.pixels.begin() + std::ptrdiff_t(img.pixels.size()), out.pixels.end())};
        return colours(band, band.height);
    }();
    EXPECT_TRUE(strip.count(app::kStripBackground)) << "a dark band";
    EXPECT_TRUE(strip.count(metrics::artifactLegend(c.t, c.r)[1].colour)) << "the bleeding swatch is drawn";
    app::releaseTextCaches();
}

}  // namespace
}  // namespace st
