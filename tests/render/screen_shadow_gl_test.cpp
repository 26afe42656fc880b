// Seed 001's screen-space path (filter.screenSpace "blur", renderer/render/screen_shadow.h) on
// llvmpipe: no blur is the unblurred factor, the blur is the CPU's separable Gaussian of the same
// mask and widens a straight shadow edge by the Gaussian's 10-90 % width, the depth-aware weight
// keeps a near occluder's darkness off the background behind its silhouette, the measured factor
// is the one the image shows, and every shipped preset renders with the path on.
#include "renderer/render/measure_pass.h"
#include "renderer/render/screen_shadow.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings_json.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

using namespace st;

namespace {
class ScreenShadowGLTest : public test::GLTest {};

// Rows bottom first, as GL reads them; `components` floats per texel.
std::vector<float> readTexture(GLuint texture, GLenum format, int components, int width, int height) {
    std::vector<float> out(std::size_t(width) * std::size_t(height) * std::size_t(components));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture, 0, format, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
    return out;
}

// The box of box-over-plane seen from above; the sun in the +X direction 45 degrees up, so the
// box's shadow on the ground spans x in [-5, -1], z in [-1, 1] and its edges at z = +-1 run
// along screen rows.
Settings topDownBox() {
    Settings s = test::boxOverPlaneView({-3.0f, 8.0f, 0.2f}, {-3.0f, 0.0f, 0.0f}, 40.0f);
    s.light.azimuth = 0.0f;
    s.light.elevation = 45.0f;
    s.cascades.count = 1;
    s.cascades.mapSize = 1024;
    s.filter.kind = FilterKind::Hard;
    s.filter.screenSpace = ScreenSpace::Blur;
    s.filter.screenDepthSigma = 0.0f;
    s.output = {160, 120, View::Shadow};
    return s;
}

// The box seen from the front with the sun behind it: its front face (toward the camera) faces
// away from the sun (mask 0) in front of lit ground a few metres farther back.
Settings frontBox() {
    Settings s = test::boxOverPlaneView({0.0f, 6.0f, 9.0f}, {0.0f, 2.0f, 0.0f}, 40.0f);
    s.light.azimuth = -90.0f;  // the sun toward -Z: shadows fall toward the camera, in front of the box
    s.light.elevation = 50.0f;
    s.cascades.count = 1;
    s.cascades.mapSize = 512;
    s.filter.kind = FilterKind::Pcf2x2;
    s.filter.screenSpace = ScreenSpace::Blur;
    s.filter.screenDownsample = 2;
    s.filter.screenBlurRadius = 4;
    s.output = {160, 120, View::Shadow};
    return s;
}

// The CPU's version of the path (shaders/screen_*.frag) in double precision, from the mask's
// (factor, depth) texels, bottom row first: block mean of the surface texels at the nearest
// depth, separable Gaussian with sigma = (r + 1) / 2 over surface taps (edge texels repeated,
// renormalised), bilinear upsample over surface taps. Depth weights off (screenDepthSigma 0).
std::vector<double> cpuPath(const std::vector<float>& mask, int w, int h, int n, int r) {
    const int lw = (w + n - 1) / n, lh = (h + n - 1) / n;
    std::vector<double> f(std::size_t(lw) * lh, 1.0), z(std::size_t(lw) * lh, 0.0);
    auto at = [&](int x, int y) { return std::size_t(y) * std::size_t(lw) + std::size_t(x); };
    for (int y = 0; y < lh; ++y)
        for (int x = 0; x < lw; ++x) {
            double sum = 0.0, count = 0.0, zNear = 0.0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::size_t k = std::size_t(std::min(y * n + j, h - 1)) * w + std::size_t(std::min(x * n + i, w - 1));
                    if (mask[2 * k + 1] <= 0.0f) continue;
                    sum += mask[2 * k], count += 1.0;
                    zNear = zNear == 0.0 ? mask[2 * k + 1] : std::min(zNear, double(mask[2 * k + 1]));
                }
            if (count > 0.0) f[at(x, y)] = sum / count, z[at(x, y)] = zNear;
        }
    const double sigma = 0.5 * (r + 1);
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<double> out = f;
        for (int y = 0; y < lh; ++y)
            for (int x = 0; x < lw; ++x) {
                if (z[at(x, y)] <= 0.0) continue;
                double sum = 0.0, weights = 0.0;
                for (int k = -r; k <= r; ++k) {
                    const int xx = axis == 0 ? std::clamp(x + k, 0, lw - 1) : x;
                    const int yy = axis == 1 ? std::clamp(y + k, 0, lh - 1) : y;
                    if (z[at(xx, yy)] <= 0.0) continue;
                    const double wk = std::exp(-k * k / (2.0 * sigma * sigma));
                    sum += wk * f[at(xx, yy)], weights += wk;
                }
                out[at(x, y)] = sum / weights;
            }
        f = out;
    }
    std::vector<double> result(std::size_t(w) * h, 1.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t p = std::size_t(y) * w + x;
            if (mask[2 * p + 1] <= 0.0f) continue;
            const double ax = (x + 0.5) / n - 0.5, ay = (y + 0.5) / n - 0.5;
            const int x0 = int(std::floor(ax)), y0 = int(std::floor(ay));
            double sum = 0.0, weights = 0.0;
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    const int xx = std::clamp(x0 + i, 0, lw - 1), yy = std::clamp(y0 + j, 0, lh - 1);
                    if (z[at(xx, yy)] <= 0.0) continue;
                    const double wb = (i ? ax - x0 : 1.0 - (ax - x0)) * (j ? ay - y0 : 1.0 - (ay - y0));
                    sum += wb * f[at(xx, yy)], weights += wb;
                }
            result[p] = sum / weights;
        }
    return result;
}

// Where the profile first rises through `level` after index `from`, linearly interpolated.
double crossing(const std::vector<double>& v, std::size_t from, double level) {
    for (std::size_t i = from; i + 1 < v.size(); ++i)
        if (v[i] < level && v[i + 1] >= level) return double(i) + (level - v[i]) / (v[i + 1] - v[i]);
    return -1.0;
}
}  // namespace

TEST(ScreenShadowTest, WeightsAreTheNormalisedGaussianOfTheRadius) {
    EXPECT_EQ(screenBlurWeights(0)[0], 1.0f);
    EXPECT_EQ(screenBlurWeights(0)[1], 0.0f);
    for (int r : {1, 4, 16}) {
        const auto w = screenBlurWeights(r);
        double sum = w[0];
        for (int k = 1; k <= r; ++k) sum += 2.0 * w[std::size_t(k)];
        EXPECT_NEAR(sum, 1.0, 1e-6) << r;
        const double sigma = 0.5 * (r + 1);  // ratio of tap r to tap 0: exp(-r^2 / (2 sigma^2))
        EXPECT_NEAR(w[std::size_t(r)] / w[0], std::exp(-r * r / (2.0 * sigma * sigma)), 1e-6) << r;
    }
    EXPECT_THROW(screenBlurWeights(17), std::invalid_argument);
    EXPECT_EQ(screenShadowBytes(160, 90, 2), std::size_t(160 * 90 * 16 + 2 * 80 * 45 * 8));
    EXPECT_EQ(screenLowSize(90, 4), 23);
}

// Radius 0 at full size is no blur: the factor the measurement pass computes with the path off,
// exactly. Every step is exact then (one tap of weight 1, x * 1 / 1), and mask and measurement
// evaluate the same shadowFactor() on the same fragments into float targets.
TEST_F(ScreenShadowGLTest, RadiusZeroAtFullSizeIsTheUnblurredFactor) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    MeasurePass measure;
    Settings s = frontBox();
    s.filter.kind = FilterKind::PcfNxN;
    s.filter.size = 5;
    s.filter.screenSpace = ScreenSpace::Off;
    r.render(s);
    const MeasureSamples off = measure.run(r, s, r.plan().csProj * r.plan().vsView);
    s.filter.screenSpace = ScreenSpace::Blur;
    s.filter.screenDownsample = 1;
    s.filter.screenBlurRadius = 0;
    r.render(s);
    ASSERT_NE(r.screenShadow(), nullptr);
    std::vector<float> result = readTexture(r.screenShadow()->resultTexture(), GL_RED, 1, s.output.width, s.output.height);
    int receivers = 0, partial = 0;
    for (int y = 0; y < s.output.height; ++y)
        for (int x = 0; x < s.output.width; ++x) {
            const std::size_t i = std::size_t(y) * s.output.width + x;  // measure rows: top first
            if (!off.receiver(i)) continue;
            ++receivers;
            const float f = off.shadow[i].y;
            partial += f > 0.01f && f < 0.99f;
            ASSERT_EQ(result[std::size_t(s.output.height - 1 - y) * s.output.width + x], f) << x << ", " << y;
        }
    EXPECT_GT(receivers, 5000);
    EXPECT_GT(partial, 50);  // PCF penumbrae are in view: the identity is tested on fractions too
}

// The blur is the CPU's separable Gaussian of the GPU's own mask, at full and half size, and it
// widens the hard edge of the box's shadow to the Gaussian's 10-90 % width, 2.563 sigma.
TEST_F(ScreenShadowGLTest, BlurIsTheSeparableGaussianAndWidensAHardEdge) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    for (int n : {1, 2}) {
        Settings s = topDownBox();
        s.filter.screenDownsample = n;
        s.filter.screenBlurRadius = 4;
        r.render(s);
        const int w = s.output.width, h = s.output.height;
        const std::vector<float> mask = readTexture(r.screenShadow()->maskTexture(), GL_RG, 2, w, h);
        const std::vector<float> gpu = readTexture(r.screenShadow()->resultTexture(), GL_RED, 1, w, h);
        const std::vector<double> cpu = cpuPath(mask, w, h, n, 4);
        double worst = 0.0;
        int blurred = 0;
        for (std::size_t i = 0; i < gpu.size(); ++i) {
            worst = std::max(worst, std::abs(gpu[i] - cpu[i]));
            blurred += std::abs(gpu[i] - mask[2 * i]) > 0.05;
        }
        EXPECT_LT(worst, 1e-5) << "downsample " << n;
        EXPECT_GT(blurred, 200) << "downsample " << n;
        // The column through the shadow's middle (x = -3) crosses its edges z = +-1 at right angles.
        const auto px = test::projectToPixel(r, {-3.0f, 0.0f, 0.0f});
        ASSERT_TRUE(px);
        const int column = px->x;
        std::vector<double> raw, soft;  // bottom row first: rows rising toward -Z
        for (int y = 0; y < h; ++y) {
            raw.push_back(mask[2 * (std::size_t(y) * w + column)]);
            soft.push_back(gpu[std::size_t(y) * w + column]);
        }
        // From the shadow's centre row toward the top: the edge at z = -1 goes from dark to lit.
        const std::size_t centre = std::size_t(h - 1 - px->y);
        ASSERT_LT(raw[centre], 0.5);
        const double rawWidth = crossing(raw, centre, 0.9) - crossing(raw, centre, 0.1);
        const double softWidth = crossing(soft, centre, 0.9) - crossing(soft, centre, 0.1);
        const double expected = 2.563 * 0.5 * (4 + 1) * n;  // full-size pixels
        EXPECT_LT(rawWidth, 1.0) << "the hard filter's edge is a step";
        EXPECT_NEAR(softWidth, expected, 0.5 * n + 0.3) << "downsample " << n;
    }
}

// Below the front face of the box (mask 0, facing away from the sun) lies lit ground 1.45x as
// far. With the depth-aware weight (sigma 0.1 of the view depth) no ground pixel whose own
// surface is lit within the blur's reach is darkened by more than 0.035: each of the three
// depth-weighted steps that can mix the two (blur x, blur y, upsample) lets a tap 30 % nearer
// through at exp(-0.5 (0.3 / 0.1)^2) = 0.011 of its Gaussian weight at most, so <= 3 x 0.011.
// Without it the box's darkness spreads onto the ground (the control, which must show it).
TEST_F(ScreenShadowGLTest, DepthAwareWeightKeepsTheOccludersEdgeOffTheBackground) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    double worstAware = 0.0, worstPlain = 0.0;
    int farSide = 0;
    for (float sigma : {0.1f, 0.0f}) {
        Settings s = frontBox();
        s.filter.screenDepthSigma = sigma;
        r.render(s);
        const int w = s.output.width, h = s.output.height;
        const std::vector<float> mask = readTexture(r.screenShadow()->maskTexture(), GL_RG, 2, w, h);
        const std::vector<float> gpu = readTexture(r.screenShadow()->resultTexture(), GL_RED, 1, w, h);
        const int reach = (s.filter.screenBlurRadius + 1) * s.filter.screenDownsample + 1;
        int count = 0;
        double worst = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t p = std::size_t(y) * w + x;
                const float z = mask[2 * p + 1];
                if (z <= 0.0f || mask[2 * p] < 1.0f) continue;
                bool nearDark = false, ownLit = true;
                for (int dy = -reach; dy <= reach; ++dy)
                    for (int dx = -reach; dx <= reach; ++dx) {
                        const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
                        const std::size_t q = std::size_t(yy) * w + xx;
                        const float zq = mask[2 * q + 1];
                        if (zq <= 0.0f) continue;
                        if (zq < 0.7f * z && mask[2 * q] < 0.5f) nearDark = true;
                        if (std::abs(zq - z) < 0.3f * z && mask[2 * q] < 1.0f) ownLit = false;
                    }
                if (!nearDark || !ownLit) continue;
                ++count;
                worst = std::max(worst, 1.0 - double(gpu[p]));
            }
        (sigma > 0.0f ? worstAware : worstPlain) = worst;
        farSide = std::max(farSide, count);
    }
    EXPECT_GT(farSide, 50) << "the built scene shows lit ground behind the dark face";
    EXPECT_LE(worstAware, 0.035);
    EXPECT_GT(worstPlain, 0.2) << "control: without the depth weight the edge bleeds";
    std::printf("far side of the step: %d px, darkened at most %.4f depth-aware, %.4f plain\n", farSide, worstAware,
                worstPlain);
}

// The factor `measure` scores is the factor the image shows: the measurement pass's own mask
// equals the renderer's upsampled mask on every receiver, and the shadow view's pixels are that
// factor in sRGB (8-bit rounding: 1 step). And the path changes the factor (not a no-op).
TEST_F(ScreenShadowGLTest, MeasuredFactorIsTheImagesFactor) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    MeasurePass measure;
    Settings s = frontBox();
    s.filter.screenSpace = ScreenSpace::Off;
    r.render(s);
    const MeasureSamples off = measure.run(r, s, r.plan().csProj * r.plan().vsView);
    s.filter.screenSpace = ScreenSpace::Blur;
    const Rgba8Image image = test::renderImage(r, s);
    const int w = s.output.width, h = s.output.height;
    const std::vector<float> result = readTexture(r.screenShadow()->resultTexture(), GL_RED, 1, w, h);
    const MeasureSamples on = measure.run(r, s, r.plan().csProj * r.plan().vsView);
    int receivers = 0, changed = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (!on.receiver(i)) continue;
            ++receivers;
            const float f = on.shadow[i].y;
            ASSERT_EQ(f, result[std::size_t(h - 1 - y) * w + x]) << x << ", " << y;
            const int expected = int(std::lround(std::pow(std::clamp(f, 0.0f, 1.0f), 1.0f / 2.2f) * 255.0f));
            ASSERT_NEAR(int(test::pixelAt(image, {x, y}).r), expected, 1) << x << ", " << y;
            changed += std::abs(f - off.shadow[i].y) > 0.05f;
        }
    EXPECT_GT(receivers, 5000);
    EXPECT_GT(changed, 100);
}

// Every shipped preset (presets/*.json, engines/, scenarios/; the glTF scenes are the goldens'
// business) renders and measures with the path on at half and quarter size, in every main view,
// with no GL error (the fixture fails on any KHR_debug message), and reports the path's cost.
TEST_F(ScreenShadowGLTest, EveryShippedPresetRendersWithThePathOn) {
    namespace fs = std::filesystem;
    std::vector<fs::path> presets;
    for (const char* dir : {"", "engines", "scenarios"})
        for (const auto& e : fs::directory_iterator(fs::path(ST_PRESET_DIR) / dir))
            if (e.path().extension() == ".json") presets.push_back(e.path());
    std::sort(presets.begin(), presets.end());
    ASSERT_GT(presets.size(), 20u);
    MeasurePass measure;
    for (const fs::path& preset : presets) {
        SCOPED_TRACE(preset.string());
        Settings s = loadPreset(preset);
        s.filter.screenSpace = ScreenSpace::Blur;
        s.filter.screenDownsample = preset.stem().string().size() % 2 ? 2 : 4;
        s.output.width = 160;
        s.output.height = 90;
        s.cascades.mapSize = std::min(s.cascades.mapSize, 256);
        for (int& size : s.cascades.mapSizes) size = std::min(size, 256);
        s.path.frames = 0;
        s.path.keyframes.clear();
        Scene scene = loadScene(s.scene, preset.parent_path(), SceneOptions{.ground = s.ground});
        Renderer r(scene);
        const FrameStats stats = r.render(s);
        if (s.output.view == View::Side) continue;  // the side camera's image filters the maps
        const std::size_t contact = s.filter.contact != ContactShadows::Off ? 160u * 90u * 4u : 0u;  // its R32F result
        EXPECT_EQ(stats.screenShadowBytes, screenShadowBytes(160, 90, s.filter.screenDownsample) + contact);
        EXPECT_GE(stats.filterMapBytes, stats.screenShadowBytes);
        EXPECT_GT(stats.gpuScreenShadowMs, 0.0);
        EXPECT_GE(stats.gpuFilterMs, stats.gpuScreenShadowMs);
        EXPECT_GT(stats.gpuScreenBlurMs, 0.0);
        EXPECT_LT(stats.gpuScreenBlurMs, stats.gpuScreenShadowMs);
        if (preset.stem() == "default") {
            for (View v : {View::Shaded, View::Cascades, View::TexelDensity, View::Side}) {
                s.output.view = v;
                r.render(s);
            }
            measure.run(r, s, r.plan().csProj * r.plan().vsView);
        }
    }
}
