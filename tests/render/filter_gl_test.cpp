// The shadow filters on llvmpipe (debug context: a GL error fails the test): every kernel takes
// receiver-plane bias, Gaussian weights and padding change what they should, and every filter
// renders every shipped preset.
#include "renderer/scene/scene.h"
#include "renderer/settings/enum_names.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace st;

namespace {
class FilterGLTest : public test::GLTest {};

// A low sun on the box-over-plane scene with a tiny constant bias and no slope bias: the plane
// shows acne under every kernel unless the receiver-plane bias removes it.
Settings acneSettings() {
    Settings s = test::boxOverPlaneView({0.0f, 9.0f, 16.0f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    s.light.azimuth = 30.0f;
    s.light.elevation = 20.0f;
    s.cascades.mapSize = 512;
    s.bias = {.constant = 0.001f, .slope = 0.0f, .normalOffset = 0.0f, .receiverPlane = false};
    s.output = {160, 120, View::Shadow};
    return s;
}

int darkPixels(const Rgba8Image& img) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) n += img.pixels[i] < 128;
    return n;
}

// Surface pixels (grey in the shadow view; the sky is blue) the shadow darkens at all.
int shadedPixels(const Rgba8Image& img) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4)
        n += img.pixels[i] == img.pixels[i + 2] && img.pixels[i] < 245;
    return n;
}

// Surface pixels between shadow and light.
int penumbraPixels(const Rgba8Image& img) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4)
        n += img.pixels[i] == img.pixels[i + 2] && img.pixels[i] > 8 && img.pixels[i] < 247;
    return n;
}

int differingPixels(const Rgba8Image& a, const Rgba8Image& b) {
    int n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4) n += a.pixels[i] != b.pixels[i];
    return n;
}

struct Kernel {
    FilterKind kind;
    int size;
    FilterWeights weights;
};
const Kernel kKernels[] = {{FilterKind::Hard, 3, FilterWeights::Box},
                           {FilterKind::Pcf2x2, 3, FilterWeights::Box},
                           {FilterKind::PcfNxN, 3, FilterWeights::Box},
                           {FilterKind::PcfNxN, 7, FilterWeights::Gaussian}};

std::string nameOf(const Kernel& k) {
    return std::string(enumName(k.kind)) + " " + std::to_string(k.size) + " " + std::string(enumName(k.weights));
}
}  // namespace

TEST_F(FilterGLTest, ReceiverPlaneBiasRemovesAcneWithEveryPcfKernel) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    for (const Kernel& k : kKernels) {
        Settings s = acneSettings();
        s.filter.kind = k.kind;
        s.filter.size = k.size;
        s.filter.weights = k.weights;
        const Rgba8Image off = test::renderImage(r, s);
        s.bias.receiverPlane = true;
        const Rgba8Image on = test::renderImage(r, s);
        const int total = off.width * off.height;
        EXPECT_GT(differingPixels(off, on), total / 50) << nameOf(k);
        // Acne darkens the lit plane: the bias must take most of it away, and leave the box's shadow.
        EXPECT_LT(shadedPixels(on), shadedPixels(off) / 2) << nameOf(k) << ": shaded " << shadedPixels(on) << " vs "
                                                            << shadedPixels(off);
        EXPECT_GT(darkPixels(on), total / 200) << nameOf(k) << ": the box's shadow is gone";
    }
}

TEST_F(FilterGLTest, GaussianWeightsChangeOnlyThePenumbra) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = acneSettings();
    s.light.elevation = 55.0f;
    s.bias.constant = 0.02f;
    s.filter.kind = FilterKind::PcfNxN;
    s.filter.size = 7;
    const Rgba8Image box = test::renderImage(r, s);
    s.filter.weights = FilterWeights::Gaussian;
    const Rgba8Image gauss = test::renderImage(r, s);
    int penumbra = 0, changedOutside = 0, changed = 0;
    for (std::size_t i = 0; i < box.pixels.size(); i += 4) {
        const bool soft = box.pixels[i] > 5 && box.pixels[i] < 250;
        penumbra += soft;
        changed += box.pixels[i] != gauss.pixels[i];
        changedOutside += !soft && std::abs(int(box.pixels[i]) - int(gauss.pixels[i])) > 5;
    }
    EXPECT_GT(penumbra, 50);
    EXPECT_GT(changed, penumbra / 4);
    EXPECT_EQ(changedOutside, 0);
}

// Padding grows the light boxes: same scene, coarser texels, so the image changes; the box's
// shadow stays where it was.
TEST_F(FilterGLTest, PaddingGrowsTheLightBoxesByTheKernelsReach) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = acneSettings();
    s.bias.constant = 0.02f;
    s.filter.kind = FilterKind::PcfNxN;
    s.filter.size = 9;
    const Rgba8Image plain = test::renderImage(r, s);
    const float plainTexel = r.plan().cascades[0].texelWorldSize;
    s.filter.padding = true;
    const Rgba8Image padded = test::renderImage(r, s);
    // 9 taps reach 5 texels: the map holds the slice in 512 - 10 texels.
    EXPECT_NEAR(r.plan().cascades[0].texelWorldSize / plainTexel, 512.0 / 502.0, 1e-4);
    EXPECT_GT(differingPixels(plain, padded), 0);
    EXPECT_NEAR(darkPixels(plain), darkPixels(padded), plain.width * plain.height / 100);
}

// Every filter (with each of its switches) over every shipped preset, tiny: no GL error, and
// the shaded image is not blank.
TEST_F(FilterGLTest, EveryFilterRendersEveryShippedPreset) {
    std::vector<std::filesystem::path> presets;
    for (const auto& e : std::filesystem::directory_iterator(ST_PRESET_DIR))
        if (e.path().extension() == ".json") presets.push_back(e.path());
    std::sort(presets.begin(), presets.end());
    ASSERT_GE(presets.size(), 5u);
    const auto kinds = enumNames<FilterKind>();
    for (const auto& file : presets) {
        Settings s = loadPreset(file);
        Scene scene = loadScene(s.scene, ST_PRESET_DIR);
        Renderer r(scene);
        s.output.width = 64;
        s.output.height = 36;
        s.cascades.mapSize = 256;
        for (std::size_t k = 0; k < kinds.size(); ++k)
            for (int variant = 0; variant < 2; ++variant) {
                s.filter.kind = static_cast<FilterKind>(k);
                s.filter.weights = variant ? FilterWeights::Gaussian : FilterWeights::Box;
                s.filter.padding = variant == 1;
                s.filter.mipmaps = s.filter.moments16 = variant == 1;
                s.bias.receiverPlane = variant == 1 && !isMomentFilter(s.filter.kind);
                // Moment filters need the array storage, PCSS one depth texture: the atlas and
                // per-texture presets refuse them (ValidationTest), so only those are skipped.
                if (const auto issues = validate(s); !issues.empty()) {
                    EXPECT_EQ(issues.size(), 1u) << file.filename() << " " << kinds[k];
                    EXPECT_NE(issues.front().find("needs cascades.storage"), std::string::npos) << issues.front();
                    continue;
                }
                const Rgba8Image img = test::renderImage(r, s);
                int distinct = 0;
                for (std::size_t i = 4; i < img.pixels.size(); i += 4) distinct += img.pixels[i] != img.pixels[0];
                EXPECT_GT(distinct, 0) << file.filename() << " " << kinds[k] << ": a flat image";
            }
    }
}

// PCSS's penumbra comes from the sun's disc: wider with the angular diameter, and with a point
// sun no wider than the 2x2 comparison's. PCSS's taps span the penumbra less the bilinear texel
// (shadow_sampling.glsl), so a disc whose penumbra is about a texel draws the 2x2 ramp: with one
// 512 map over this view (texels of 0.16 m) that is a 2 deg sun (0.17 m from the box's top across
// the light), hence the smallest disc here is 5 deg.
TEST_F(FilterGLTest, PcssPenumbraGrowsWithTheSunsAngularDiameter) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = acneSettings();
    s.light.elevation = 55.0f;
    s.bias = BiasSettings{};
    s.bias.receiverPlane = true;
    s.cascades.count = 1;
    s.filter.kind = FilterKind::Pcss;
    s.filter.size = 7;
    s.filter.pcssMaxRadius = 32.0f;
    auto penumbra = [&](float degrees) {
        s.light.angularDiameter = degrees;
        return penumbraPixels(test::renderImage(r, s));
    };
    const int point = penumbra(0.0f), small = penumbra(5.0f), mid = penumbra(10.0f), wide = penumbra(20.0f);
    Settings hard = s;
    hard.filter.kind = FilterKind::Pcf2x2;
    const int pcf = penumbraPixels(test::renderImage(r, hard));
    EXPECT_LE(point, pcf + pcf / 10) << point << " " << pcf;
    EXPECT_GT(small, point) << point << " " << small;
    EXPECT_GT(mid, small * 3 / 2) << small << " " << mid;
    EXPECT_GT(wide, mid * 3 / 2) << mid << " " << wide;
}
