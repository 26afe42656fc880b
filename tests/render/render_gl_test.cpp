// GL tests (EGL on llvmpipe, debug context): assertions that hold on any conformant driver.
#include "renderer/csm/culling.h"
#include "renderer/gpu/gl.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/enum_names.h"
#include "renderer/settings/settings_json.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <vector>

using namespace st;

namespace {
class RenderGLTest : public test::GLTest {};

Settings boxOverPlaneSettings() {
    Settings s = test::boxOverPlaneView({0.0f, 12.0f, 14.0f}, {0.0f, 0.0f, 0.0f}, 100.0f);
    s.light.azimuth = 30.0f;
    s.light.elevation = 55.0f;
    s.output = {320, 240, View::Shadow};
    s.filter.kind = FilterKind::Hard;
    return s;
}

// The box's shadow on y = 0: its eight corners moved along the light direction to the plane.
std::array<glm::vec3, 8> projectedBoxCorners(glm::vec3 lightDir) {
    std::array<glm::vec3, 8> out;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p((i & 1) ? 1.0f : -1.0f, (i & 2) ? 4.0f : 2.0f, (i & 4) ? 1.0f : -1.0f);
        out[i] = p + lightDir * (-p.y / lightDir.y);
    }
    return out;
}
}  // namespace

TEST_F(RenderGLTest, BoxShadowIsDarkInsideProjectionAndLitWellOutside) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = boxOverPlaneSettings();
    Rgba8Image img = test::renderImage(r, s);
    auto corners = projectedBoxCorners(r.plan().wsLightDir);
    glm::vec3 centre(0.0f);
    float radius = 0.0f;
    for (auto c : corners) centre += c / 8.0f;
    for (auto c : corners) radius = std::max(radius, glm::length(c - centre));
    int checkedInside = 0, checkedOutside = 0;
    for (auto c : corners) {  // points pulled halfway to the centre lie inside the shadow
        auto px = test::projectToPixel(r, glm::mix(centre, c, 0.5f));
        ASSERT_TRUE(px);
        EXPECT_LT(test::pixelAt(img, *px).r, 40) << "expected shadow at pixel " << px->x << "," << px->y;
        ++checkedInside;
    }
    for (int k = 0; k < 16; ++k) {  // a ring 2 m beyond the farthest corner is lit
        float a = float(k) * 6.2831853f / 16.0f;
        glm::vec3 p = centre + (radius + 2.0f) * glm::vec3(std::cos(a), 0.0f, std::sin(a));
        auto px = test::projectToPixel(r, p);
        if (!px) continue;
        glm::vec3 toCam = glm::normalize(s.camera.position - p);  // skip ground hidden by the box
        glm::vec3 q = p + toCam * (3.0f / toCam.y);
        if (std::abs(q.x) < 1.2f && std::abs(q.z) < 1.2f) continue;
        EXPECT_GT(test::pixelAt(img, *px).r, 200) << "expected light at pixel " << px->x << "," << px->y;
        ++checkedOutside;
    }
    EXPECT_EQ(checkedInside, 8);
    EXPECT_GE(checkedOutside, 8);
}

TEST_F(RenderGLTest, DefaultPresetCascadeViewShowsFourTints) {
    Settings s = loadPreset(ST_PRESET_DIR "/default.json");
    ASSERT_EQ(s.cascades.count, 4);
    s.output = {320, 180, View::Cascades};
    Scene scene = loadScene(s.scene, ST_PRESET_DIR);
    Renderer r(scene);
    Rgba8Image img = test::renderImage(r, s);
    // The first four tints (the one table, cascadeTint), sRGB-encoded, normalised to their largest channel.
    int counts[4] = {};
    for (std::size_t i = 0; i < img.pixels.size() / 4; ++i) {
        glm::vec3 c(img.pixels[i * 4], img.pixels[i * 4 + 1], img.pixels[i * 4 + 2]);
        float m = std::max({c.r, c.g, c.b});
        if (m < 30.0f) continue;
        for (int t = 0; t < 4; ++t) {
            glm::vec3 ref = glm::pow(cascadeTint(t), glm::vec3(1.0f / 2.2f));
            if (glm::length(c / m - ref / std::max({ref.r, ref.g, ref.b})) < 0.12f) ++counts[t];
        }
    }
    for (int t = 0; t < 4; ++t) EXPECT_GT(counts[t], 100) << "tint of cascade " << t << " missing";
}

TEST_F(RenderGLTest, ChangingCountAndMapSizeLeaksNoGLObjects) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s;
    s.output = {64, 64, View::Shaded};
    s.cascades.mapSize = 512;
    r.render(s);
    int live = gpu::liveObjectCount();
    for (auto [count, size] : {std::pair{2, 1024}, {8, 256}, {1, 2048}, {4, 512}}) {
        s.cascades.count = count;
        s.cascades.mapSize = size;
        FrameStats stats = r.render(s);
        EXPECT_EQ(stats.shadowMapBytes, std::size_t(count) * size * size * 4);
        EXPECT_EQ(int(stats.cascades.size()), count);
    }
    EXPECT_EQ(gpu::liveObjectCount(), live);
}

namespace {
// Share of pixels whose colour differs between two images of the same size.
double differingShare(const Rgba8Image& a, const Rgba8Image& b) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i + 3 < a.pixels.size(); i += 4)
        differ += !std::equal(&a.pixels[i], &a.pixels[i] + 3, &b.pixels[i]);
    return double(differ) / double(a.pixels.size() / 4);
}
}  // namespace

// Every value of View (taken from its names, so a view added to the enum is covered without
// touching this test) with every filter and fit. Each view must draw something of its own: its
// image differs from every other view's in a good share of the pixels.
TEST_F(RenderGLTest, EveryViewFilterAndFitRendersWithoutGLErrors) {
    const auto viewNames = enumNames<View>();
    // The views this test was written against; a new one must show up in the checks below (it
    // does, through viewNames) and in this count, once someone has looked at what it draws.
    EXPECT_EQ(viewNames.size(), 6u) << "View gained or lost a value: review this test's coverage";
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s;
    s.output = {96, 64, View::Shaded};
    s.output.sideTexels = true;  // the side view with its texel points
    s.cascades.mapSize = 256;
    for (FilterKind f : {FilterKind::Hard, FilterKind::Pcf2x2, FilterKind::PcfNxN})
        for (FitMode fit : {FitMode::Cascade, FitMode::Scene, FitMode::Sphere}) {
            s.filter.kind = f;
            s.cascades.fit = fit;
            s.cascades.selection = fit == FitMode::Scene ? Selection::Map : Selection::Interval;
            s.cascades.zExtension = fit == FitMode::Sphere ? ZExtension::Pancake : ZExtension::SceneBounds;
            s.bias.receiverPlane = f == FilterKind::PcfNxN;
            s.cascades.blendBand = 0.2f;
            std::vector<Rgba8Image> images;
            for (std::size_t v = 0; v < viewNames.size(); ++v) {
                s.output.view = static_cast<View>(v);
                EXPECT_EQ(r.render(s).cascades.size(), 4u) << viewNames[v];
                images.push_back({r.width(), r.height(), r.readRgba8()});
            }
            for (std::size_t a = 0; a < images.size(); ++a)
                for (std::size_t b = a + 1; b < images.size(); ++b)
                    EXPECT_GT(differingShare(images[a], images[b]), 0.05)
                        << "views " << viewNames[a] << " and " << viewNames[b] << " look alike (filter "
                        << enumName(f) << ", fit " << enumName(fit) << ")";
        }
}

TEST_F(RenderGLTest, CullingSkipsCastersOutsideEachLightBox) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    r.setOptions({.naive = true});  // per draw item (culling_cache_gl_test.cpp: per cluster)
    Settings s;
    s.output = {64, 64, View::Shaded};
    s.cascades.mapSize = 256;
    FrameStats stats = r.render(s);
    ASSERT_EQ(stats.cascades.size(), 4u);
    const DrawItem& tower = scene.draws.back();  // the last item built is the far tower
    EXPECT_FALSE(csm::casterNeeded(tower.wsBounds, r.plan().cascades[0], false));
    EXPECT_TRUE(csm::casterNeeded(tower.wsBounds, r.plan().cascades[3], false));
    for (int c = 0; c < 4; ++c) {
        int expected = 0;
        for (const DrawItem& d : scene.draws) expected += csm::casterNeeded(d.wsBounds, r.plan().cascades[c], false);
        EXPECT_EQ(stats.cascades[c].casterDraws, expected) << "cascade " << c;
        EXPECT_LT(stats.cascades[c].casterDraws, int(scene.draws.size())) << "cascade " << c << " culled nothing";
    }
    EXPECT_LT(stats.cascades[0].texelWorldSize, stats.cascades[3].texelWorldSize);
}

TEST_F(RenderGLTest, SideViewDrawsEveryCascadeLightBoxInItsTint) {
    Settings s = loadPreset(ST_PRESET_DIR "/default.json");
    s.output = {320, 240, View::Side};
    Scene scene = loadScene(s.scene, ST_PRESET_DIR);
    Renderer r(scene);
    Rgba8Image img = test::renderImage(r, s);
    for (int c = 0; c < s.cascades.count; ++c) {
        // Visible wireframe pixels are the tint itself, sRGB-encoded.
        glm::vec3 want = glm::pow(cascadeTint(c), glm::vec3(1.0f / 2.2f)) * 255.0f;
        int hits = 0;
        for (std::size_t i = 0; i < img.pixels.size() / 4; ++i) {
            glm::vec3 px(img.pixels[i * 4], img.pixels[i * 4 + 1], img.pixels[i * 4 + 2]);
            hits += glm::length(px - want) < 6.0f;
        }
        EXPECT_GT(hits, 20) << "light box of cascade " << c << " not drawn";
    }
}
