// Counted work per pass (renderer/render/pass_work.h): the same settings give the same counts,
// and each count equals an independent count on a scene whose answer is known.
#include "renderer/csm/filter_taps.h"
#include "renderer/render/pass_counters.h"
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <cstdint>

using namespace st;

namespace {
class PassWorkGLTest : public test::GLTest {};

// Looking straight down at the ground 1 m below, far from the box: the ground's two triangles
// fill the view, nothing in front of them, so every pixel is shaded exactly once.
Settings groundFillingTheView() {
    Settings s = test::boxOverPlaneView({10.0f, 1.0f, 10.0f}, {10.0f, 0.0f, 10.2f}, 50.0f);
    s.output.width = 160;
    s.output.height = 90;
    s.cascades.count = 2;
    s.cascades.mapSize = 256;
    return s;
}

std::uint64_t u64(std::size_t v) { return std::uint64_t(v); }

// Fragment-shader invocations of passes that cover `pixels` pixels exactly once. Drivers may count
// more than the pixels covered: llvmpipe (Mesa 22.3) shades in 4x4 blocks and counts a W x H
// fullscreen triangle as W x (H + 4) (measured at 64..512 texels per side), the ground's two
// triangles at 160x90 as 15440. So: at least every pixel, and within 10 %.
void expectCovers(std::uint64_t fragments, std::uint64_t pixels, const char* what) {
    EXPECT_GE(fragments, pixels) << what;
    EXPECT_LE(fragments, pixels + pixels / 10) << what;
}

FrameStats redrawn(Renderer& r, const Settings& s) {
    r.invalidateMaps();
    return r.render(s);
}

// Square sheets of 2 x 2 m facing +z, one every 4 m along -z, one draw each in this order;
// double-sided, so from either end of the stack every sheet is drawn and the nearest hides the rest.
Scene sheetStack(int sheets) {
    Scene s;
    s.materials.push_back(Material{.baseColor = {0.9f, 0.3f, 0.2f, 1.0f}, .doubleSided = true});
    for (int k = 0; k < sheets; ++k) {
        const float z = -4.0f * float(k);
        const auto base = std::uint32_t(s.vertices.size());
        for (float y : {-1.0f, 1.0f})
            for (float x : {-1.0f, 1.0f}) s.vertices.push_back({{x, y, z}, {0, 0, 1}, {}});
        s.draws.push_back(DrawItem{.firstIndex = std::uint32_t(s.indices.size()), .indexCount = 6, .material = 0});
        s.indices.insert(s.indices.end(), {base, base + 1, base + 3, base, base + 3, base + 2});
    }
    finalizeBounds(s);
    return s;
}

// Pixels of the image other than the colour of its top-left corner (the sky there).
std::uint64_t coveredPixels(const std::vector<std::uint8_t>& px) {
    std::uint64_t covered = 0;
    for (std::size_t i = 0; i + 3 < px.size(); i += 4)
        covered += px[i] != px[0] || px[i + 1] != px[1] || px[i + 2] != px[2];
    return covered;
}
}  // namespace

TEST_F(PassWorkGLTest, TheContextCountsPipelineStatistics) {
    EXPECT_TRUE(PassCounters().supported()) << "llvmpipe has ARB_pipeline_statistics_query";
}

TEST_F(PassWorkGLTest, TheSameSettingsTwiceGiveTheSameWork) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = test::boxOverPlaneView({6.0f, 5.0f, 8.0f}, {0.0f, 1.0f, 0.0f}, 60.0f);
    s.output.width = 200;
    s.output.height = 120;
    r.render(s);  // first-use allocations
    const FrameStats a = redrawn(r, s);
    const FrameStats b = redrawn(r, s);
    EXPECT_EQ(a.work, b.work);
    EXPECT_GT(a.work.main.fragments, 0u);
    EXPECT_GT(a.work.shadow.fragments, 0u);
    EXPECT_GT(a.work.main.samplesPassed, 0u);
    EXPECT_GT(a.work.shadow.samplesPassed, 0u);
    EXPECT_EQ(a.work.main.samplesPassed, b.work.main.samplesPassed);
    // Samples that passed the depth test were shaded; llvmpipe counts invocations before it.
    EXPECT_LE(a.work.main.samplesPassed, a.work.main.fragments);
    EXPECT_LE(a.work.shadow.samplesPassed, a.work.shadow.fragments);
    EXPECT_EQ(a.work.cascades.size(), std::size_t(s.cascades.count));
}

TEST_F(PassWorkGLTest, TheGroundFillingTheViewShadesEachPixelOnce) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    const Settings s = groundFillingTheView();
    const FrameStats f = redrawn(r, s);
    const PassWork& m = f.work.main;
    ASSERT_EQ(f.mainTriangles, 2u) << "only the ground is in view";
    expectCovers(m.fragments, u64(160 * 90), "main pass");
    // One layer, nothing in front: exactly one sample per pixel passes, where invocations count
    // llvmpipe's 4x4 blocks.
    EXPECT_EQ(m.samplesPassed, u64(160 * 90));
    EXPECT_EQ(m.primitives, 2u);
    EXPECT_EQ(m.clippedPrimitives, 2u);
    EXPECT_EQ(m.vertices, 6u);
    EXPECT_EQ(m.draws, 1u);  // one range of one multi-draw
    EXPECT_EQ(m.texelsCleared, u64(160 * 90));
    // pcf2x2: one bilinear compare of 4 D32F texels per fragment.
    EXPECT_EQ(m.filterTaps, m.fragments);
    EXPECT_EQ(m.bytesRead, m.fragments * 4u * 4u);
    EXPECT_EQ(m.computeInvocations, 0u);
    EXPECT_EQ(f.work.filter, PassWork{});
    EXPECT_EQ(f.work.depthBounds, PassWork{});
}

TEST_F(PassWorkGLTest, EachRedrawnMapCountsItsTexelsAndCasters) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    const Settings s = groundFillingTheView();
    const FrameStats f = redrawn(r, s);
    PassWork sum;
    for (int i = 0; i < s.cascades.count; ++i) {
        const PassWork& w = f.work.cascades[std::size_t(i)];
        const CascadeStats& c = f.cascades[std::size_t(i)];
        ASSERT_TRUE(c.redrawn);
        EXPECT_EQ(w.texelsCleared, u64(256 * 256)) << i;
        EXPECT_EQ(w.bytesWritten, u64(4 * 256 * 256)) << i;  // D32F
        EXPECT_EQ(w.primitives, u64(c.casterTriangles)) << i;
        EXPECT_EQ(w.vertices, 3u * u64(c.casterTriangles)) << i;
        EXPECT_GT(w.fragments, 0u) << i;
        EXPECT_EQ(w.filterTaps, 0u) << i;
        sum += w;
    }
    EXPECT_EQ(f.work.shadow, sum);
}

TEST_F(PassWorkGLTest, AKeptMapDidNoWork) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    const Settings s = groundFillingTheView();
    const FrameStats first = redrawn(r, s);
    const FrameStats second = r.render(s);  // still camera: every map kept
    for (int i = 0; i < s.cascades.count; ++i) {
        EXPECT_FALSE(second.cascades[std::size_t(i)].redrawn) << i;
        EXPECT_EQ(second.work.cascades[std::size_t(i)], PassWork{}) << i;
        EXPECT_NE(first.work.cascades[std::size_t(i)], PassWork{}) << i;
    }
    EXPECT_EQ(second.work.shadow, PassWork{});
    EXPECT_EQ(second.work.main, first.work.main);  // the main pass is drawn every frame
}

TEST_F(PassWorkGLTest, MomentMapsAreTwoFullscreenPassesPerLayer) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = groundFillingTheView();
    s.filter.kind = FilterKind::Vsm;
    s.filter.blurRadius = 2;
    const FrameStats f = redrawn(r, s);
    const std::uint64_t texels = 2u * 256u * 256u;  // two layers
    const PassWork& w = f.work.filter;
    EXPECT_EQ(w.draws, 4u);
    expectCovers(w.fragments, 2u * texels, "moment passes");  // the fullscreen triangle covers each texel once
    EXPECT_EQ(w.primitives, 4u);
    EXPECT_EQ(w.filterTaps, 2u * texels * 5u);
    EXPECT_EQ(w.bytesRead, texels * 5u * (4u + 16u));  // depth, then the RGBA32F scratch
    EXPECT_EQ(w.bytesWritten, texels * (16u + 8u));    // scratch, then RG32F moments
    EXPECT_EQ(momentFormat(FilterKind::Vsm, false).bytesPerTexel, csm::momentBytesPerTexel(FilterKind::Vsm, false));
    EXPECT_EQ(momentFormat(FilterKind::Msm, true).bytesPerTexel, csm::momentBytesPerTexel(FilterKind::Msm, true));
    // The main pass fetches the moments once per fragment: 4 RG32F texels.
    EXPECT_EQ(f.work.main.filterTaps, f.work.main.fragments);
    EXPECT_EQ(f.work.main.bytesRead, f.work.main.fragments * 4u * 8u);
}

TEST_F(PassWorkGLTest, TheDepthReductionRunsOneInvocationPerSixteenBySixteenTexels) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = groundFillingTheView();
    s.cascades.depthBounds = DepthBounds::Fit;
    const FrameStats f = redrawn(r, s);
    const PassWork& w = f.work.depthBounds;
    // ceil(160 / 128) x ceil(90 / 16) groups of 8 x 1, each invocation 16 x 16 texels
    // (shaders/depth_bounds_comp.glsl).
    EXPECT_EQ(w.computeInvocations, 2u * 6u * 8u);
    expectCovers(w.fragments, u64(160 * 90), "depth prepass");  // one layer of ground
    EXPECT_EQ(w.primitives, 2u);
    EXPECT_EQ(w.texelsCleared, u64(160 * 90));
    EXPECT_EQ(w.bytesRead, u64(4 * 160 * 90));
}

TEST_F(PassWorkGLTest, TheScreenSpacePathFiltersInItsMaskAndTheMainPassReadsOneFactor) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = groundFillingTheView();
    s.filter.screenSpace = ScreenSpace::Blur;
    s.filter.screenDownsample = 2;
    s.filter.screenBlurRadius = 1;
    const FrameStats f = redrawn(r, s);
    const std::uint64_t full = 160u * 90u, low = 80u * 45u;
    // The mask (every pixel once) and four fullscreen passes: 3 at low size, 1 at full size.
    expectCovers(f.work.filter.fragments, full + 3u * low + full, "screen-space passes");
    EXPECT_EQ(f.work.filter.draws, 1u + 4u);
    // Mask: pcf2x2's one tap per fragment shaded; downsample 2 x 2^2, blurs 1 + 3 each, upsample 5.
    const std::uint64_t blurTaps = low * 8u + 2u * low * 4u + full * 5u;
    ASSERT_GT(f.work.filter.filterTaps, blurTaps);
    expectCovers(f.work.filter.filterTaps - blurTaps, full, "mask taps");
    EXPECT_EQ(f.work.main.filterTaps, f.work.main.fragments);
    EXPECT_EQ(f.work.main.bytesRead, f.work.main.fragments * 4u);  // one R32F factor
}

namespace {

// sheetStack(sheets) seen along its axis, from the front sheet's side or from the back one's.
Settings lookingAlongTheStack(int sheets, bool fromFront) {
    Settings s;
    s.output = {160, 120, View::Shaded};
    s.cascades.mapSize = 256;
    s.camera.nearPlane = 0.3f;
    s.camera.farPlane = 60.0f;
    const float back = -4.0f * float(sheets - 1);
    s.camera.position = {0.0f, 0.0f, fromFront ? 6.0f : back - 6.0f};
    s.camera.target = {0.0f, 0.0f, fromFront ? -1.0f : back + 1.0f};
    return s;
}

}  // namespace

// llvmpipe counts fragment-shader invocations before the depth test, so they are the same in
// any draw order; the samples that passed it are not. The naive path draws the stack in scene
// order: front to back from its +z end, where only the nearest sheet's pixels pass, and back to
// front from the other end, where every sheet passes where it is drawn.
TEST_F(PassWorkGLTest, SamplesPassedShowOverdrawThatFragmentsDoNot) {
    constexpr int sheets = 4;
    Scene scene = sheetStack(sheets);
    Renderer r(scene);
    r.setOptions(RenderOptions{.naive = true});
    PassWork frontToBack, backToFront;
    std::uint64_t coveredFront = 0, coveredBack = 0;
    for (bool fromFront : {true, false}) {
        const Settings s = lookingAlongTheStack(sheets, fromFront);
        const PassWork w = r.render(s).work.main;
        (fromFront ? frontToBack : backToFront) = w;
        (fromFront ? coveredFront : coveredBack) = coveredPixels(r.readRgba8());
    }
    ASSERT_GT(coveredFront, 0u);
    EXPECT_EQ(frontToBack.samplesPassed, coveredFront);
    // Mirror-image views: the same coverage, within a row of pixels for the mirrored rasterisation.
    EXPECT_NEAR(double(coveredBack), double(coveredFront), 160.0);
    EXPECT_NEAR(double(backToFront.fragments), double(frontToBack.fragments), 0.01 * double(frontToBack.fragments));
    // Back to front every sheet passes where it is drawn: sheets 6, 10, 14 and 18 m away cover
    // 1 + (6/10)^2 + (6/14)^2 + (6/18)^2 = 1.65 times the nearest one's pixels.
    EXPECT_GE(backToFront.samplesPassed, coveredBack + coveredBack / 2);
    EXPECT_LE(backToFront.samplesPassed, backToFront.fragments);
    EXPECT_GT(backToFront.samplesPassed, frontToBack.samplesPassed);
}

// A sample fit reduces the depth buffer twice when its splits follow the seen range (the range
// first, then each cascade's samples) and once when they do not: the range comes along.
TEST_F(PassWorkGLTest, ASampleFitWithSplitsThatDoNotFollowTheRangeReducesOnce) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = groundFillingTheView();
    s.cascades.fit = FitMode::Samples;
    s.cascades.depthBounds = DepthBounds::Fit;
    const FrameStats twice = redrawn(r, s);
    s.cascades.depthBounds = DepthBounds::Off;
    const FrameStats once = redrawn(r, s);
    EXPECT_EQ(twice.work.depthBounds.computeInvocations, 2u * once.work.depthBounds.computeInvocations);
    EXPECT_EQ(once.work.depthBounds.computeInvocations, 2u * 6u * 8u);
    EXPECT_EQ(once.work.depthBounds.bytesRead, u64(4 * 160 * 90));  // the prepass's D32F depth, read once
    EXPECT_EQ(twice.work.depthBounds.bytesRead, 2u * once.work.depthBounds.bytesRead);
    // Both saw the same depths: the range reported does not depend on which pass reduced it.
    ASSERT_TRUE(once.depthBounds.seen && twice.depthBounds.seen);
    EXPECT_FLOAT_EQ(once.depthBounds.vsMin, twice.depthBounds.vsMin);
    EXPECT_FLOAT_EQ(once.depthBounds.vsMax, twice.depthBounds.vsMax);
}

// With depth bounds the main pass draws over the prepass's depth (LEQUAL, no depth writes), so it
// shades each covered pixel once even back to front, where without them every sheet passes.
TEST_F(PassWorkGLTest, OverTheDepthPrepassTheMainPassShadesEachPixelOnce) {
    constexpr int sheets = 4;
    Scene scene = sheetStack(sheets);
    Renderer r(scene);
    Settings s = lookingAlongTheStack(sheets, false);  // back to front: the worst order
    s.cascades.count = 1;  // manual: the seen range moves no split, so both frames draw the same map
    s.cascades.scheme = SplitScheme::Manual;
    const PassWork without = r.render(s).work.main;
    const std::vector<std::uint8_t> imageWithout = r.readRgba8();
    s.cascades.depthBounds = DepthBounds::Fit;
    const FrameStats with = r.render(s);
    const std::uint64_t covered = coveredPixels(r.readRgba8());
    ASSERT_GT(covered, 0u);
    EXPECT_GE(without.samplesPassed, covered + covered / 2);
    EXPECT_EQ(with.work.main.samplesPassed, covered);
    EXPECT_EQ(with.work.main.fragments, without.fragments);  // rasterised as before, shaded once
    // The same picture: every nearest fragment passed LEQUAL against its own prepass depth.
    EXPECT_EQ(r.readRgba8(), imageWithout);
}

// RenderOptions::shadeMain off (what a tune's evaluation draws): the main pass draws coverage
// only, so the image is not the shaded one, but the counted work is the same to the count, with
// a hard and a wide filter, and with a masked sheet whose every fragment is discarded in front
// of an opaque one.
TEST_F(PassWorkGLTest, AnUnshadedMainPassCountsTheSameWork) {
    Scene scene = sheetStack(2);
    scene.materials.push_back(Material{.baseColor = {0.2f, 0.9f, 0.2f, 0.2f}, .alphaMask = true, .doubleSided = true});
    scene.draws[0].material = 1;  // the nearer sheet: alpha 0.2 under the cutoff 0.5
    Renderer r(scene);
    Settings s;
    s.output = {160, 120, View::Shaded};
    s.cascades.mapSize = 256;
    s.camera.position = {0.3f, 0.2f, 6.0f};
    s.camera.target = {0.0f, 0.0f, -1.0f};
    s.camera.nearPlane = 0.3f;
    s.camera.farPlane = 60.0f;
    for (FilterKind kind : {FilterKind::Hard, FilterKind::PcfNxN}) {
        s.filter.kind = kind;
        r.setOptions({});
        const FrameStats shaded = redrawn(r, s);
        const std::vector<std::uint8_t> image = r.readRgba8();
        r.setOptions(RenderOptions{.shadeMain = false});
        const FrameStats unshaded = redrawn(r, s);
        EXPECT_EQ(shaded.work, unshaded.work) << "filter " << int(kind);
        EXPECT_GT(shaded.work.main.fragments, shaded.work.main.samplesPassed) << "the masked sheet's fragments ran and were discarded";
        EXPECT_NE(r.readRgba8(), image) << "unshaded, the image is not the shaded one";
    }
}

namespace {
// The sheet stack seen from in front and a little to the side, small: the kept-pass tests' view.
Settings obliqueStackView() {
    Settings s;
    s.output = {160, 120, View::Shaded};
    s.cascades.mapSize = 256;
    s.camera.position = {0.3f, 0.2f, 6.0f};
    s.camera.target = {0.0f, 0.0f, -1.0f};
    return s;
}
}  // namespace

// Unshaded, the main pass of the same camera is drawn once: the next frames keep its counted work
// (their own filter's taps added) and its image, and count what a renderer drawing it afresh counts.
TEST_F(PassWorkGLTest, AnUnshadedMainPassOfTheSameCameraIsKept) {
    const Scene scene = sheetStack(2);
    Renderer r(scene);
    r.setOptions(RenderOptions{.shadeMain = false});
    Settings s = obliqueStackView();
    EXPECT_FALSE(redrawn(r, s).mainKept);
    for (FilterKind kind : {FilterKind::PcfNxN, FilterKind::Pcss}) {
        s.filter.kind = kind;
        const FrameStats kept = redrawn(r, s);
        Renderer fresh(scene);
        fresh.setOptions(RenderOptions{.shadeMain = false});
        const FrameStats drawn = redrawn(fresh, s);
        EXPECT_TRUE(kept.mainKept) << int(kind);
        EXPECT_FALSE(drawn.mainKept);
        EXPECT_EQ(kept.work, drawn.work) << int(kind);
        EXPECT_EQ(kept.mainTriangles, drawn.mainTriangles);
        EXPECT_EQ(r.readRgba8(), fresh.readRgba8());
    }
    s.camera.position.x += 0.5f;
    EXPECT_FALSE(redrawn(r, s).mainKept) << "another camera draws it";
    r.setOptions({});
    EXPECT_FALSE(redrawn(r, s).mainKept) << "shaded, it is always drawn";
    r.setOptions(RenderOptions{.shadeMain = false});
    EXPECT_FALSE(redrawn(r, s).mainKept) << "after a shaded frame the target holds the shaded image";
}

// The depth prepass of an unshaded frame is kept like the main pass: a frame of the same camera
// that changes only shadow settings reduces the kept depth, and counts and places everything as
// a renderer that draws the prepass afresh.
TEST_F(PassWorkGLTest, AnUnshadedDepthPrepassOfTheSameCameraIsKept) {
    const Scene scene = sheetStack(3);
    Renderer r(scene);
    r.setOptions(RenderOptions{.shadeMain = false});
    Settings s = obliqueStackView();
    s.cascades.depthBounds = DepthBounds::Fit;
    s.cascades.fit = FitMode::Samples;
    EXPECT_FALSE(redrawn(r, s).prepassKept);
    for (float slope : {2.0f, 0.5f}) {
        s.bias.slope = slope;
        const FrameStats kept = redrawn(r, s);
        Renderer fresh(scene);
        fresh.setOptions(RenderOptions{.shadeMain = false});
        const FrameStats drawn = redrawn(fresh, s);
        EXPECT_TRUE(kept.prepassKept) << slope;
        EXPECT_FALSE(drawn.prepassKept);
        EXPECT_GT(drawn.work.depthBounds.fragments, 0u) << "the prepass's draw is counted";
        EXPECT_EQ(kept.work, drawn.work) << slope;
        EXPECT_EQ(kept.splits, drawn.splits);
        EXPECT_EQ(kept.depthBounds.vsMin, drawn.depthBounds.vsMin);
        EXPECT_EQ(kept.depthBounds.vsMax, drawn.depthBounds.vsMax);
        ASSERT_EQ(r.plan().cascades.size(), fresh.plan().cascades.size());
        for (std::size_t i = 0; i < r.plan().cascades.size(); ++i)
            EXPECT_EQ(r.plan().cascades[i].viewProj, fresh.plan().cascades[i].viewProj) << i;
        EXPECT_EQ(r.readRgba8(), fresh.readRgba8());
    }
    s.camera.position.x += 0.5f;
    EXPECT_FALSE(redrawn(r, s).prepassKept) << "another camera draws it";
    s.cascades.depthBounds = DepthBounds::Off;
    s.cascades.fit = FitMode::Cascade;
    redrawn(r, s);  // no prepass: the main pass writes the target's depth
    s.cascades.depthBounds = DepthBounds::Fit;
    s.cascades.fit = FitMode::Samples;
    EXPECT_FALSE(redrawn(r, s).prepassKept) << "after a frame without it the target's depth is the main pass's";
    r.setOptions({});
    EXPECT_FALSE(redrawn(r, s).prepassKept) << "shaded, it is always drawn";
}
