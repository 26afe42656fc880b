// The measurement pass reads back what the main pass shows: same coverage, same shadow factor,
// same texel density, with cascades chosen from the cascade camera.
#include "renderer/image/image_io.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include <algorithm>
#include <cmath>

namespace st {
namespace {

class MeasurePassGLTest : public test::GLTest {
protected:
    // The main pass's image of `s` in `view`, and the measured samples of the same frame.
    std::pair<Rgba8Image, MeasureSamples> renderAndSample(Settings s, View view) {
        s.output.view = view;
        auto& e = session_.entryFor(s, ST_PRESET_DIR);
        MeasureSamples samples = metrics::sampleFrame(*e.renderer, session_.pass(), s, s);
        return {Rgba8Image{e.renderer->width(), e.renderer->height(), e.renderer->readRgba8()}, std::move(samples)};
    }
    metrics::MeasureSession session_;
};

float encodeSrgb(float linear) { return std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f); }

TEST_F(MeasurePassGLTest, FilteredFactorIsWhatTheShadowViewShows) {
    const auto [img, s] = renderAndSample(test::presetAtTestSize("dx-sdk-csm11"), View::Shadow);  // PCF + blend
    int compared = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.covered(i)) continue;
        const float shown = float(img.pixels[4 * i]) / 255.0f;
        const float expected = encodeSrgb(s.normal[i].w > 0.0f ? s.shadow[i].y : 0.0f);  // main.frag: N.L > 0
        ASSERT_NEAR(shown, expected, 1.0f / 255.0f) << "pixel " << i % s.width << "," << i / s.width;
        ++compared;
    }
    EXPECT_GT(compared, 40000);
}

TEST_F(MeasurePassGLTest, CoverageIsTheMainPassCoverage) {
    const auto [img, s] = renderAndSample(test::presetAtTestSize("default"), View::Shaded);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const bool sky = img.pixels[4 * i] == 158 && img.pixels[4 * i + 1] == 184 && img.pixels[4 * i + 2] == 217;
        ASSERT_EQ(s.covered(i), !sky) << "pixel " << i % s.width << "," << i / s.width;
    }
}

TEST_F(MeasurePassGLTest, UnfilteredTestIsBinaryAndIsTheHardFilter) {
    Settings settings = test::presetAtTestSize("default");
    settings.filter.kind = FilterKind::Hard;
    const auto [img, s] = renderAndSample(settings, View::Shadow);
    int dark = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.covered(i)) continue;
        ASSERT_TRUE(s.shadow[i].x == 0.0f || s.shadow[i].x == 1.0f);
        ASSERT_EQ(s.shadow[i].x, s.shadow[i].y);
        dark += s.receiver(i) && s.shadow[i].x == 0.0f;
    }
    EXPECT_GT(dark, 100);
}

// main.frag's texel-density colour for a measured density, shaded by N.L as the view does.
glm::vec3 densityViewColor(float pixelsPerTexel, float nDotL) {
    const float v = std::clamp(std::log2(pixelsPerTexel) / 4.0f, -1.0f, 1.0f);
    const glm::vec3 ideal(0.0f, 0.8f, 0.1f);
    const glm::vec3 c = v < 0.0f ? glm::mix(ideal, glm::vec3(0.1f, 0.2f, 1.0f), -v)
                                 : glm::mix(ideal, glm::vec3(1.0f, 0.1f, 0.0f), v);
    return glm::pow(glm::clamp(c * (0.5f + 0.5f * std::max(nDotL, 0.0f)), 0.0f, 1.0f), glm::vec3(1.0f / 2.2f));
}

TEST_F(MeasurePassGLTest, TexelDensityViewShowsTheMeasuredDensity) {
    const auto [img, s] = renderAndSample(test::presetAtTestSize("default"), View::TexelDensity);
    int compared = 0, off = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s.covered(i) || s.cascade(i) < 0) continue;
        const glm::vec3 expected = densityViewColor(s.shadow[i].w, s.normal[i].w) * 255.0f;
        const glm::vec3 shown(img.pixels[4 * i], img.pixels[4 * i + 1], img.pixels[4 * i + 2]);
        const glm::vec3 diff = glm::abs(shown - expected);
        off += std::max({diff.x, diff.y, diff.z}) > 1.5f;
        ++compared;
    }
    EXPECT_GT(compared, 40000);
    EXPECT_LT(off, compared / 1000);  // the same formula: only rounding differs
}

TEST_F(MeasurePassGLTest, CascadesFollowTheCascadeCameraNotTheObserver) {
    const Settings observer = test::presetAtTestSize("default");
    Settings away = observer;  // the cascade camera 60 m further back along the same view
    const glm::vec3 back = glm::normalize(observer.camera.position - observer.camera.target) * 60.0f;
    away.camera.position += back;
    away.camera.target += back;
    auto& e = session_.entryFor(observer, ST_PRESET_DIR);
    const MeasureSamples same = metrics::sampleFrame(*e.renderer, session_.pass(), observer, observer);
    const MeasureSamples moved = metrics::sampleFrame(*e.renderer, session_.pass(), away, observer);
    EXPECT_EQ(same.position, moved.position);  // the observer sees the same points
    const std::size_t nearGround = std::size_t(170) * same.width + same.width / 2;  // bottom centre
    ASSERT_TRUE(same.covered(nearGround));
    EXPECT_EQ(same.cascade(nearGround), 0);
    EXPECT_GT(moved.cascade(nearGround), 0);  // 60 m away, that point is a far cascade's
}

// The hard test the shadow pass computes is the one main.frag shows, pixel for pixel, on every
// path the pass is specialised for (storage, selection, receiver plane, blend band): 0 or 255
// where the factor is binary, the blend's grey within a step in the band.
TEST_F(MeasurePassGLTest, HardTestIsTheImagesOnEverySpecialisedPath) {
    struct Case {
        const char* name;
        void (*apply)(Settings&);
    };
    const Case cases[] = {
        {"array, interval", [](Settings&) {}},
        {"array, map selection, normal offset", [](Settings& s) { s.cascades.selection = Selection::Map; s.bias.normalOffset = 1.0f; }},
        {"atlas, receiver plane", [](Settings& s) { s.cascades.storage = CascadeStorage::Atlas; s.bias.receiverPlane = true; }},
        {"textures, blend band", [](Settings& s) { s.cascades.storage = CascadeStorage::Textures; s.cascades.blendBand = 0.2f; }},
    };
    for (const Case& c : cases) {
        Settings settings = test::presetAtTestSize("default");
        settings.filter.kind = FilterKind::Hard;
        c.apply(settings);
        const auto [img, s] = renderAndSample(settings, View::Shadow);
        int compared = 0, dark = 0;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (!s.receiver(i)) continue;
            const int shown = img.pixels[4 * i];  // N.L > 0 here
            ASSERT_NEAR(float(shown), 255.0f * encodeSrgb(s.shadow[i].y), 1.0f)
                << c.name << ", pixel " << i % s.width << "," << i / s.width;
            // Outside the blend band the factor is the hard test itself.
            if (s.shadow[i].y == 0.0f || s.shadow[i].y == 1.0f) ASSERT_EQ(s.shadow[i].x, s.shadow[i].y) << c.name;
            ++compared, dark += shown == 0;
        }
        EXPECT_GT(compared, 20000) << c.name;
        EXPECT_GT(dark, 100) << c.name;
    }
}

// The filtered factor is the image's for every filter kind: each is its own specialised program.
TEST_F(MeasurePassGLTest, FilteredFactorIsTheImagesForEveryFilterKind) {
    for (FilterKind kind : {FilterKind::Pcf2x2, FilterKind::PcfNxN, FilterKind::Vsm, FilterKind::Evsm2,
                            FilterKind::Evsm4, FilterKind::Msm, FilterKind::Pcss}) {
        Settings settings = test::presetAtTestSize("default");
        settings.filter.kind = kind;
        const auto [img, s] = renderAndSample(settings, View::Shadow);
        int compared = 0, between = 0;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (!s.receiver(i)) continue;
            ASSERT_NEAR(float(img.pixels[4 * i]), 255.0f * encodeSrgb(s.shadow[i].y), 1.0f)
                << int(kind) << ", pixel " << i % s.width << "," << i / s.width;
            ++compared, between += s.shadow[i].y > 0.05f && s.shadow[i].y < 0.95f;
        }
        EXPECT_GT(compared, 20000) << int(kind);
        EXPECT_GT(between, 20) << int(kind) << ": a filter softens some edge";
    }
}

// A view's surfaces are drawn once: candidates that change only shadow settings reuse them and
// read what a fresh pass reads; another camera or sun draws them again.
TEST_F(MeasurePassGLTest, SurfacesAreKeptPerViewAndSunNotPerShadowSetting) {
    Settings first = test::presetAtTestSize("default");
    auto& e = session_.entryFor(first, ST_PRESET_DIR);
    MeasurePass pass;
    const MeasureSamples before = metrics::sampleFrame(*e.renderer, pass, first, first);
    Settings second = first;
    second.filter.kind = FilterKind::PcfNxN;
    second.bias.slope *= 2.0f;
    second.cascades.mapSize /= 2;
    const MeasureSamples kept = metrics::sampleFrame(*e.renderer, pass, second, second);
    EXPECT_EQ(pass.surfacesDrawn(), 1u);
    EXPECT_EQ(pass.surfacesReused(), 1u);
    MeasurePass fresh;
    const MeasureSamples drawn = metrics::sampleFrame(*e.renderer, fresh, second, second);
    EXPECT_EQ(kept.position, drawn.position);
    EXPECT_EQ(kept.normal, drawn.normal);
    EXPECT_EQ(kept.geometry, drawn.geometry);
    EXPECT_EQ(kept.shadow, drawn.shadow);
    EXPECT_NE(kept.surface, 0u);
    EXPECT_EQ(kept.surface, before.surface);  // what lets the truth cache skip comparing the vectors
    EXPECT_NE(drawn.surface, kept.surface);

    Settings moved = second;
    moved.camera.position.x += 1.0f;
    EXPECT_NE(metrics::sampleFrame(*e.renderer, pass, moved, moved).surface, kept.surface);
    EXPECT_EQ(pass.surfacesDrawn(), 2u);
    Settings sun = second;
    sun.light.azimuth += 10.0f;
    const MeasureSamples lit = metrics::sampleFrame(*e.renderer, pass, sun, sun);
    EXPECT_EQ(pass.surfacesDrawn(), 3u);
    EXPECT_NE(lit.normal, kept.normal);  // N.L moved with the sun
}

// The surfaces kept are the most recently used that fit the budget: room for one, two views
// alternating draw every time; room for two, each view's once.
TEST_F(MeasurePassGLTest, SurfacesKeptAreTheRecentOnesThatFitTheBudget) {
    const Settings a = test::presetAtTestSize("default");
    const Settings b = [&] {
        Settings moved = a;
        moved.camera.position.y += 2.0f;
        return moved;
    }();
    auto& e = session_.entryFor(a, ST_PRESET_DIR);
    const std::size_t one = MeasurePass::surfaceBytes(a.output.width, a.output.height);
    for (const auto& [room, drawn] : {std::pair{one, 4u}, std::pair{2 * one, 2u}}) {
        MeasurePass pass(room);
        for (const Settings* s : {&a, &b, &a, &b}) metrics::sampleFrame(*e.renderer, pass, *s, *s);
        EXPECT_EQ(pass.surfacesDrawn(), drawn) << room << " bytes";
        EXPECT_EQ(pass.surfacesReused(), 4u - drawn) << room << " bytes";
    }
}

TEST_F(MeasurePassGLTest, CoveredShadowTexelsAreCounted) {
    const Settings s = test::presetAtTestSize("box-over-plane");
    auto& e = session_.entryFor(s, ST_PRESET_DIR);
    e.renderer->render(s);
    const std::vector<std::size_t> covered = coveredShadowTexels(e.renderer->shadowMaps());
    ASSERT_EQ(covered.size(), 2u);
    const std::size_t all = std::size_t(s.cascades.mapSize) * std::size_t(s.cascades.mapSize);
    EXPECT_GT(covered[0], 0u);
    EXPECT_LE(covered[1], all);
}

}  // namespace
}  // namespace st
