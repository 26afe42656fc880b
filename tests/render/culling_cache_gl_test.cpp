// Cluster culling, batched draws and cached cascade maps (issue 11 items 2 and 3): the images
// never change, the counts match an independent count, and maps are redrawn exactly when needed.
#include "renderer/csm/caster_culling.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings_json.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace st;

namespace {
class CullingCacheGLTest : public test::GLTest {};

int differingPixels(const Rgba8Image& a, const Rgba8Image& b) {
    int n = 0;
    for (std::size_t i = 0; i + 3 < a.pixels.size(); i += 4)
        n += a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] || a.pixels[i + 2] != b.pixels[i + 2];
    return n;
}

Settings yardShadow() {
    Settings s;
    s.output = {320, 180, View::Shadow};
    s.cascades.mapSize = 512;
    return s;
}

// Renders s with culling on and off (fresh maps each) and expects the same pixels; returns the
// triangles submitted over all cascades with culling on and off.
std::pair<std::size_t, std::size_t> expectCullingInvisible(Renderer& r, Settings s, const std::string& what) {
    std::size_t on = 0, off = 0;
    s.cascades.casterCulling = true;
    r.invalidateMaps();
    FrameStats a = r.render(s);
    Rgba8Image culled{r.width(), r.height(), r.readRgba8()};
    s.cascades.casterCulling = false;
    r.invalidateMaps();
    FrameStats b = r.render(s);
    Rgba8Image all{r.width(), r.height(), r.readRgba8()};
    EXPECT_EQ(differingPixels(culled, all), 0) << what;
    for (const auto& c : a.cascades) on += c.casterTriangles;
    for (const auto& c : b.cascades) off += c.casterTriangles;
    return {on, off};
}
}  // namespace

TEST_F(CullingCacheGLTest, CasterCullingNeverChangesTheShadowImageOfTheYard) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    std::size_t culledAway = 0;
    for (float azimuth : {35.0f, 200.0f})
        for (Selection sel : {Selection::Interval, Selection::Map})
            for (float band : {0.0f, 0.2f}) {
                s.light.azimuth = azimuth;
                s.cascades.selection = sel;
                s.cascades.blendBand = band;
                s.filter = {FilterKind::PcfNxN, 7};
                s.bias.normalOffset = 1.0f;
                auto [on, off] = expectCullingInvisible(r, s, "azimuth " + std::to_string(azimuth));
                EXPECT_LE(on, off);
                culledAway += off - on;
            }
    EXPECT_GT(culledAway, 0u) << "caster culling culled nothing: the test shows nothing";
}

TEST_F(CullingCacheGLTest, CasterCullingNeverChangesTheShadowImageOfTruckTown) {
    const std::filesystem::path preset = ST_PRESET_DIR "/scenes/truck-town.json";
    Settings s = loadPreset(preset);
    const std::filesystem::path dir = preset.parent_path();
    Scene scene;
    try {
        scene = loadScene(s.scene, dir);
    } catch (const SceneError& e) {
        GTEST_SKIP() << "no truck_town in ../shared/assets: " << e.what();
    }
    Renderer r(scene);
    s.output = {320, 180, View::Shadow};
    s.cascades.mapSize = 1024;
    auto [on, off] = expectCullingInvisible(r, s, "truck-town");
    // Every triangle meets every light box there (the lower bound is the whole scene), so only
    // the swept footprint can drop any.
    EXPECT_LT(on, off) << "the swept footprint culled nothing";
}

TEST_F(CullingCacheGLTest, BatchedClusteredPathDrawsTheNaiveImage) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    std::size_t fewest = scene.triangleCount();
    for (View v : {View::Shaded, View::Side})
        for (glm::vec3 target : {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(-20.0f, 1.0f, 30.0f)}) {
            Settings s = yardShadow();
            s.output.view = v;
            s.camera.target = target;  // the second looks away from most of the yard
            r.setOptions({.naive = true});
            Rgba8Image naive = test::renderImage(r, s);
            r.setOptions({});
            FrameStats stats = r.render(s);
            Rgba8Image batched{r.width(), r.height(), r.readRgba8()};
            EXPECT_EQ(differingPixels(naive, batched), 0) << "view " << int(v);
            if (v == View::Shaded) fewest = std::min(fewest, stats.mainTriangles);
        }
    EXPECT_LT(fewest, scene.triangleCount()) << "frustum culling culled nothing";
}

TEST_F(CullingCacheGLTest, StatsCountWhatTheCullingKeepsAndTheLowerBound) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    FrameStats stats = r.render(s);
    const csm::CascadePlan& plan = r.plan();
    const auto& clusters = r.sceneGpu().clustered().clusters;
    for (int i = 0; i < s.cascades.count; ++i) {
        const csm::CascadeFit& fit = plan.cascades[std::size_t(i)];
        const csm::CasterVolume v = csm::casterVolume(s, plan.camera, plan.splits, i, fit);
        std::size_t kept = 0, tris = 0;
        for (const Cluster& k : clusters)
            if (csm::casterMayShadow(k.wsBounds, v)) ++kept, tris += k.indexCount / 3;
        // The lower bound from the scene's own triangles, in scene order, with the box rule
        // written out: x,y overlap and not wholly behind or in front (no pancake here).
        std::size_t bound = 0;
        for (std::size_t t = 0; t + 3 <= scene.indices.size(); t += 3) {
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (int c = 0; c < 3; ++c) {
                glm::vec3 p(fit.lsView * glm::vec4(scene.vertices[scene.indices[t + std::size_t(c)]].position, 1.0f));
                lo = glm::min(lo, p), hi = glm::max(hi, p);
            }
            const csm::Aabb& b = fit.lsBox;
            bound += hi.x >= b.min.x && lo.x <= b.max.x && hi.y >= b.min.y && lo.y <= b.max.y && hi.z >= b.min.z &&
                     lo.z <= b.max.z;
        }
        const CascadeStats& c = stats.cascades[std::size_t(i)];
        EXPECT_EQ(c.casterClusters, kept) << "cascade " << i;
        EXPECT_EQ(c.casterTriangles, tris) << "cascade " << i;
        EXPECT_EQ(c.lowerBoundTriangles, bound) << "cascade " << i;
        EXPECT_EQ(c.casterClustersTotal, clusters.size());
        EXPECT_GT(c.casterDraws, 0);
        EXPECT_LT(c.casterDraws, int(scene.draws.size())) << "batches should merge the yard's items";
    }
}

TEST_F(CullingCacheGLTest, AStillCameraRedrawsNothingForTenFramesAndKeepsTheImage) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    FrameStats first = r.render(s);
    Rgba8Image image0{r.width(), r.height(), r.readRgba8()};
    for (const auto& c : first.cascades) EXPECT_TRUE(c.redrawn);
    for (int frame = 1; frame <= 10; ++frame) {
        FrameStats f = r.render(s);
        for (std::size_t i = 0; i < f.cascades.size(); ++i) {
            EXPECT_FALSE(f.cascades[i].redrawn) << "frame " << frame << " cascade " << i;
            EXPECT_EQ(f.cascades[i].mapReason, "unchanged");
            EXPECT_EQ(f.cascades[i].casterTriangles, first.cascades[i].casterTriangles);  // what the map holds
        }
    }
    EXPECT_EQ(differingPixels(image0, {r.width(), r.height(), r.readRgba8()}), 0);
}

TEST_F(CullingCacheGLTest, ChangesThatAffectAMapRedrawItAndOthersDoNot) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    r.render(s);
    auto expectAll = [&](const Settings& t, bool redrawn, const std::string& reasonPart) {
        FrameStats f = r.render(t);
        for (const auto& c : f.cascades) {
            EXPECT_EQ(c.redrawn, redrawn) << reasonPart << ": " << c.mapReason;
            EXPECT_NE(c.mapReason.find(reasonPart), std::string::npos) << c.mapReason;
        }
    };
    Settings t = s;
    t.bias.constant = 0.05f;  // read by the main pass only
    t.filter.kind = FilterKind::Hard;
    expectAll(t, false, "unchanged");
    t.cascades.mapSize = 1024;
    expectAll(t, true, "cascades.mapSize changed (reallocate)");
    t.light.azimuth += 10.0f;
    expectAll(t, true, "light matrix changed");
    t.cascades.zExtension = ZExtension::None;  // same boxes as pancake...
    r.render(t);
    t.cascades.zExtension = ZExtension::Pancake;  // ...but casters in front are now clamped in
    FrameStats f = r.render(t);
    for (const auto& c : f.cascades) EXPECT_TRUE(c.redrawn) << c.mapReason;
}

TEST_F(CullingCacheGLTest, StableFitRedrawsOnlyCascadesWhoseSnappedMatrixMoved) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    s.cascades.fit = FitMode::Sphere;
    s.cascades.stabilize = true;
    s.cascades.zExtension = ZExtension::SceneBounds;
    r.render(s);
    int kept = 0, redrawn = 0;
    for (int step = 1; step <= 6; ++step) {
        std::vector<glm::mat4> before;
        for (const auto& c : r.plan().cascades) before.push_back(c.viewProj);
        s.camera.position.x += 0.01f;  // a few millimetres: far less than the far cascades' texels
        s.camera.target.x += 0.01f;
        FrameStats f = r.render(s);
        for (std::size_t i = 0; i < f.cascades.size(); ++i) {
            const bool moved = r.plan().cascades[i].viewProj != before[i];
            EXPECT_EQ(f.cascades[i].redrawn, moved) << "step " << step << " cascade " << i << ": " << f.cascades[i].mapReason;
            (moved ? redrawn : kept) += 1;
        }
    }
    EXPECT_GT(kept, 0) << "no map was kept: stable fit should hold the far ones";
    EXPECT_GT(redrawn, 0) << "no map moved: the test moved too little";
}

TEST_F(CullingCacheGLTest, UpdateIntervalRedrawsFarCascadesEveryKFrames) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    s.cascades.updateInterval = {1, 1, 2, 4};
    std::vector<std::vector<int>> drawnAt(4);
    for (int frame = 0; frame < 9; ++frame) {
        s.camera.position.x = 0.3f * float(frame);  // every matrix changes every frame (no stable fit)
        FrameStats f = r.render(s);
        for (int i = 0; i < 4; ++i) {
            if (f.cascades[std::size_t(i)].redrawn) drawnAt[std::size_t(i)].push_back(frame);
            else EXPECT_NE(f.cascades[std::size_t(i)].mapReason.find("deferred: update interval"), std::string::npos);
        }
        // A deferred map is sampled with the matrix it was drawn with.
        if (!f.cascades[3].redrawn) EXPECT_NE(r.plan().cascades[3].viewProj, csm::planCascades(s, 16.0f / 9.0f, scene.wsBounds).cascades[3].viewProj);
    }
    EXPECT_EQ(drawnAt[0], (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(drawnAt[1], (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(drawnAt[2], (std::vector<int>{0, 2, 4, 6, 8}));
    EXPECT_EQ(drawnAt[3], (std::vector<int>{0, 4, 8}));
}

TEST_F(CullingCacheGLTest, NaiveAndCacheOffRedrawEveryMapEveryFrame) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    Settings s = yardShadow();
    for (RenderOptions o : {RenderOptions{.naive = true}, RenderOptions{.cacheMaps = false}}) {
        r.setOptions(o);
        for (int frame = 0; frame < 3; ++frame)
            for (const auto& c : r.render(s).cascades) EXPECT_TRUE(c.redrawn) << c.mapReason;
    }
}

namespace {
// Sheets of 2 x 2 m facing +z, one every 4 m along -z, each a 16 x 16 grid (512 triangles, so
// the clusters split the stack between sheets before splitting a sheet). Double-sided: seen
// from either end of the stack, every sheet is drawn, and the nearest hides all the others.
Scene sheetStack(int sheets) {
    Scene s;
    s.materials.push_back(Material{.baseColor = {0.9f, 0.3f, 0.2f, 1.0f}, .doubleSided = true});
    constexpr int n = 16;
    for (int k = 0; k < sheets; ++k) {
        const float z = -4.0f * float(k);
        DrawItem item{.firstIndex = std::uint32_t(s.indices.size()), .material = 0};
        const auto base = std::uint32_t(s.vertices.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                s.vertices.push_back({{-1.0f + 2.0f * float(i) / n, -1.0f + 2.0f * float(j) / n, z}, {0, 0, 1}, {}});
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::uint32_t a = base + std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + n + 1, d = c + 1;
                s.indices.insert(s.indices.end(), {a, b, d, a, d, c});
            }
        item.indexCount = std::uint32_t(s.indices.size()) - item.firstIndex;
        s.draws.push_back(item);
    }
    finalizeBounds(s);
    return s;
}

}  // namespace

// llvmpipe shades every fragment that passes the depth test when drawn, so the main pass draws
// visible clusters front to back: from either end of a stack of sheets, only the nearest sheet's
// fragments pass, as many as the pixels the image shows it on. The clusters' build order runs
// along the stack, so without the ordering one of the two views would pass every sheet.
TEST_F(CullingCacheGLTest, MainPassDrawsClustersFrontToBackFromEitherSide) {
    constexpr int sheets = 8;
    Scene scene = sheetStack(sheets);
    Renderer r(scene);
    ASSERT_GE(r.sceneGpu().clustered().clusters.size(), std::size_t(2 * sheets));
    Settings s;
    s.output = {160, 120, View::Shaded};
    s.cascades.mapSize = 256;
    s.camera.nearPlane = 0.3f;
    s.camera.farPlane = 60.0f;
    for (float eye : {6.0f, -4.0f * (sheets - 1) - 6.0f}) {
        s.camera.position = {0.0f, 0.0f, eye};
        s.camera.target = {0.0f, 0.0f, eye > 0 ? -1.0f : -4.0f * (sheets - 1) + 1.0f};
        const std::uint64_t passed = r.render(s).work.main.samplesPassed;
        const std::vector<std::uint8_t> px = r.readRgba8();
        std::uint64_t covered = 0;  // pixels other than the sky of the top-left corner
        for (std::size_t i = 0; i + 3 < px.size(); i += 4)
            covered += px[i] != px[0] || px[i + 1] != px[1] || px[i + 2] != px[2];
        EXPECT_GT(covered, 0u) << "eye z " << eye;
        EXPECT_EQ(passed, covered) << "eye z " << eye << ": fragments of hidden sheets were shaded";
    }
}
