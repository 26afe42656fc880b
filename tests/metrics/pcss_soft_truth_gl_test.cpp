// PCSS against the soft truth of the sun's disc (issue 12, "Done when"): on the thin slab of
// builtin:stacked-slabs, whose shadow's far edge is cast by one edge 1.7 m up (the slab is 0.2 m
// thick, so a blocker search that finds its top face finds the right distance), PCSS's penumbra
// widens with the angular diameter as the truth's does and stays within a stated tolerance of
// it; its filtered error against that truth is below the hard and the 2x2 PCF's.
#include "tests/metrics/scenario_gl_util.h"

#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace st {
namespace {

using test::printFigures;

class PcssSoftTruthGLTest : public test::ScenarioGLTest {};

// Looking down on the slab's shadow, sun at azimuth 0 (from +x) and elevation 45: the shadow's
// far edge runs along z at x = -2 - 1.7 / tan(45 deg) = -3.7 on the ground. The slats of the scene
// shadow x > 11, out of view. Maps of 1024 over a 20 m view: cascade 0's texels are a few mm, so
// PCSS's kernel (capped at 32 texels) holds the widest penumbra here.
Settings slabEdge(FilterKind kind, float angularDiameter) {
    Settings s;
    s.scene = "builtin:stacked-slabs";
    s.camera.position = {-3.7f, 3.0f, 1.5f};
    s.camera.target = {-3.2f, 0.0f, 0.0f};
    s.camera.farPlane = 20.0f;
    s.light.azimuth = 0.0f;
    s.light.elevation = 45.0f;
    s.light.angularDiameter = angularDiameter;
    s.cascades.count = 2;
    s.cascades.mapSize = 1024;
    s.filter.kind = kind;
    s.filter.size = 9;
    s.filter.blockerTaps = 7;
    s.filter.pcssMaxRadius = 32.0f;
    s.measure.sunRays = 64;
    // PCSS's kernel here spans up to 64 texels of a ground tilted 45 deg to the light: with the
    // constant and slope bias alone its far taps shadow the ground itself (measured: acne 1.5 %
    // of the receivers beside the penumbra at 6 deg, filtered error above the hard filter's).
    // Receiver-plane bias compares each tap at the receiver's plane, for all three filters.
    s.bias.receiverPlane = true;
    s.output = {320, 180, View::Shaded};
    return s;
}

TEST_F(PcssSoftTruthGLTest, PcssPenumbraFollowsTheTruthsAndBeatsHardAndPcf2x2) {
    double lastTruth = 0.0, lastPcss = 0.0;
    for (float degrees : {2.0f, 6.0f}) {
        const metrics::PresetMeasurement pcss = measure(slabEdge(FilterKind::Pcss, degrees));
        const metrics::PresetMeasurement hard = measure(slabEdge(FilterKind::Hard, degrees));
        const metrics::PresetMeasurement pcf = measure(slabEdge(FilterKind::Pcf2x2, degrees));
        const metrics::PenumbraWidth& w = pcss.soft.penumbra;
        printFigures("slab edge at %.0f deg: true penumbra %.2f px (contour %zu), PCSS %.2f px (contour %zu), "
                     "hard %.2f px, 2x2 %.2f px; filtered error PCSS %.4f, hard %.4f, 2x2 %.4f",
                     degrees, w.truthPx, w.truthContour, w.filteredPx, w.filteredContour, hard.soft.penumbra.filteredPx,
                     pcf.soft.penumbra.filteredPx, pcss.soft.all.filteredError(), hard.soft.all.filteredError(),
                     pcf.soft.all.filteredError());
        ASSERT_GT(w.truthContour, 100u) << "the edge should cross the view";
        // Measured 4.97 px vs 4.66 at 2 deg, 14.75 vs 13.85 at 6 deg (+7 %; 5.35 and 15.07 before
        // the taps spanned the penumbra less the bilinear texel, issue 19): the box ramp against
        // the disc's S-curve, whose thin ends 64 rays partly miss. Tolerance 15 % of the truth.
        EXPECT_NEAR(w.filteredPx, w.truthPx, 0.15 * w.truthPx) << degrees << " deg";
        // Measured 2.6x to 3x below both; asserted 2x.
        EXPECT_LT(pcss.soft.all.filteredError(), 0.5 * hard.soft.all.filteredError()) << degrees << " deg";
        EXPECT_LT(pcss.soft.all.filteredError(), 0.5 * pcf.soft.all.filteredError()) << degrees << " deg";
        EXPECT_GT(w.truthPx, lastTruth);
        EXPECT_GT(w.filteredPx, lastPcss + 0.5 * (w.truthPx - lastTruth)) << "PCSS should widen with the sun";
        lastTruth = w.truthPx;
        lastPcss = w.filteredPx;
    }
}

// presets/scenarios/pcss-sun-3deg*.json (issue 19, part 3): box-over-plane's box (x, z in -1..1,
// y 2..4) under a sun 3 deg wide from +x at elevation e. The shadow's far edge, along z, is cast
// by the top face's edge at x = -1, y = h = 4 alone: a sun direction at elevation a puts it at
// x = -1 - h / tan(a) on the ground, so the disc (a in e -+ theta / 2) spreads it over
// [-1 - h / tan(e - theta/2), -1 - h / tan(e + theta/2)]: 0.31 m, h / sin(e) * tan(theta) = 0.26 m
// across the light. The camera looks along +x at that edge, so it runs along the image rows and
// the band's height in pixels is the projected x extent.
constexpr float kTopY = 4.0f, kFarFaceX = -1.0f;

struct FarEdge {
    double xOut = 0.0, xIn = 0.0;  // the true penumbra's ends on the ground
    double analyticPx = 0.0;       // its height in the image
};

FarEdge farEdge(const Settings& s) {
    const double e = glm::radians(double(s.light.elevation)), half = 0.5 * glm::radians(double(s.light.angularDiameter));
    FarEdge f;
    f.xOut = kFarFaceX - kTopY / std::tan(e - half);
    f.xIn = kFarFaceX - kTopY / std::tan(e + half);
    const glm::mat4 vp = metrics::observerViewProj(s);
    auto rowOf = [&](double x) {
        const glm::vec4 c = vp * glm::vec4(float(x), 0.0f, 0.0f, 1.0f);
        return 0.5 * double(c.y / c.w) * double(s.output.height);
    };
    f.analyticPx = std::abs(rowOf(f.xIn) - rowOf(f.xOut));
    return f;
}

// The product's penumbra width (metrics::penumbraWidth, the same eps as scoreSoftAccuracy) over
// the ground around the far edge only: half a metre either side of it, |z| < 0.6 (the side edges'
// penumbrae, at |z| = 1, are at most 0.26 m wide).
struct EdgeWidths {
    double truthPx = 0.0, filteredPx = 0.0;
    std::size_t truthContour = 0, filteredContour = 0;
};

EdgeWidths farEdgeWidths(const metrics::PresetMeasurement& m, const FarEdge& f) {
    const MeasureSamples& s = m.samples;
    std::vector<std::uint8_t> use(s.size(), 0);
    std::vector<float> filtered(s.size(), 0.0f);
    const double mid = 0.5 * (f.xIn + f.xOut);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const glm::vec4 p = s.position[i];
        use[i] = std::abs(p.y) < 1e-3f && std::abs(double(p.x) - mid) < 0.5 && std::abs(p.z) < 0.6f;
        filtered[i] = s.shadow[i].y;
    }
    EdgeWidths w;
    std::size_t pixels = 0;
    metrics::penumbraWidth(s, m.softTruth.visible, use, 0.0f, w.truthPx, pixels, w.truthContour);
    metrics::penumbraWidth(s, filtered, use, 0.02f, w.filteredPx, pixels, w.filteredContour);
    return w;
}

// The user's case of issue 19: the same scene measured 4.14 px of PCSS penumbra against 7.41 true.
// With the kernel capped at 8 texels (the control) PCSS spreads the far edge over about half its
// true width; at the default cap (32) it follows the disc, by the product's whole-image figure and
// on the far edge against the analytic width.
TEST_F(PcssSoftTruthGLTest, PcssUnderAThreeDegreeSunMatchesTheAnalyticPenumbraOfTheBoxEdge) {
    const Settings fixSettings = test::scenario("pcss-sun-3deg");
    const FarEdge f = farEdge(fixSettings);
    const metrics::PresetMeasurement capped = measure("pcss-sun-3deg-capped");
    const metrics::PresetMeasurement fix = measure(fixSettings);
    const EdgeWidths cw = farEdgeWidths(capped, f), fw = farEdgeWidths(fix, f);
    const metrics::PenumbraWidth &c = capped.soft.penumbra, &w = fix.soft.penumbra;
    printFigures("pcss-sun-3deg: whole image true %.2f px, PCSS %.2f px (capped at 8 texels: %.2f px); far edge "
                 "analytic %.2f px, true %.2f px (contour %zu), PCSS %.2f px (contour %zu), capped %.2f px; "
                 "filtered error %.4f (capped %.4f), acne px %zu (capped %zu)",
                 w.truthPx, w.filteredPx, c.filteredPx, f.analyticPx, fw.truthPx, fw.truthContour, fw.filteredPx,
                 fw.filteredContour, cw.filteredPx, fix.soft.all.filteredError(), capped.soft.all.filteredError(),
                 fix.soft.all.acne, capped.soft.all.acne);
    ASSERT_GT(w.truthContour, 200u) << "the shadow should fill much of the view";
    ASSERT_GT(fw.truthContour, 40u) << "the far edge should cross the view";  // 56 columns measured
    // The truth itself against the geometry: 64 stratified rays miss the disc's thin ends (a
    // fraction under 1/64 reads 0), so it reads a little under the analytic width.
    EXPECT_NEAR(fw.truthPx, f.analyticPx, 0.15 * f.analyticPx);
    // The goal of issue 19: within 15 % of the soft truth over the whole image, and of the
    // analytic width on the far edge.
    EXPECT_NEAR(w.filteredPx, w.truthPx, 0.15 * w.truthPx);
    EXPECT_NEAR(fw.filteredPx, f.analyticPx, 0.15 * f.analyticPx);
    // The control: the 8-texel cap cuts the penumbra to about 0.55 of the truth (measured); a cap
    // that held would read within 15 %, so 0.75 separates the two.
    EXPECT_LT(c.filteredPx, 0.75 * c.truthPx);
    EXPECT_LT(cw.filteredPx, 0.75 * f.analyticPx);
    // The wider kernel compares its taps on the receiver's plane (shadow_sampling.glsl, pcss):
    // without that it shadowed 2 % of the lit ground beside the penumbra (1176 px at 320x180).
    EXPECT_LT(fix.soft.all.share(fix.soft.all.acne), 0.001);
    // Against the disc, PCSS still beats the hard test, but narrowly (measured 0.0068 vs 0.0080;
    // the capped kernel 0.0031): 3 taps per side over a 16-texel radius step the ramp in thirds,
    // and the penumbra PCSS centres on the hard edge reaches into the true umbra beside the box's
    // side faces, whose true penumbra is lopsided (the box is 2 m deep along the light; 182 px of
    // light bleeding). filter.size 7 brings it to 0.0038 at 1.2x the modelled cost.
    Settings hardSettings = fixSettings;
    hardSettings.filter.kind = FilterKind::Hard;
    const metrics::PresetMeasurement hard = measure(hardSettings);
    printFigures("pcss-sun-3deg: filtered error hard %.4f, light bleeding px PCSS %zu", hard.soft.all.filteredError(),
                 fix.soft.all.lightBleeding);
    EXPECT_LT(fix.soft.all.filteredError(), hard.soft.all.filteredError());
}

}  // namespace
}  // namespace st
