// Seed 003's two views of shadow-map resolution: the texel-grid view (each map a checker of
// output.texelBlock texels in its cascade's tint) and the texels back-projected into the world
// over the side view (output.sideTexels).
#include "renderer/render/measure_pass.h"
#include "renderer/render/cascade_tints.h"
#include "renderer/render/shader_blocks.h"
#include "renderer/render/texel_cloud.h"
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>

using namespace st;

namespace {
class TexelViewsGLTest : public test::GLTest {};

float encodeSrgb(float linear) { return std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f); }

// Constant lighting (no direct light, ambient 1), so the view's colour is tint x checker alone.
Settings flatLitYard(View view) {
    Settings s;
    s.output = {320, 180, view};
    s.cascades.mapSize = 512;
    s.output.texelBlock = 8;
    s.light.intensity = 0.0f;
    s.light.ambient = 1.0f;
    return s;
}
}  // namespace

// Each pixel's block parity, worked out on the CPU from its measured world position through its
// cascade's shadow matrix, is the one the image shows (bright = even, 0.45 x tint = odd).
TEST_F(TexelViewsGLTest, TexelGridIsACheckerOfEachCascadesTexels) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    for (CascadeStorage storage : {CascadeStorage::Array, CascadeStorage::Atlas}) {
        SCOPED_TRACE(int(storage));
        Settings s = flatLitYard(View::TexelGrid);
        s.cascades.storage = storage;
        const Rgba8Image img = test::renderImage(r, s);
        MeasurePass measure;
        const MeasureSamples m = measure.run(r, s, r.plan().csProj * r.plan().vsView);
        const gpu_if::CascadeBlock block = cascadeBlock(s, r.plan());
        int compared = 0, agree = 0;
        std::set<int> cascades, parities;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(img.width) + std::size_t(x);
                const int c = m.cascade(i);
                if (!m.covered(i) || c < 0) continue;
                const glm::vec4 ts = block.cascade[c].shadowMatrix * glm::vec4(glm::vec3(m.position[i]), 1.0f);
                const glm::vec2 blocks = glm::vec2(ts) / glm::vec2(block.cascade[c].uvPerTexel) / float(s.output.texelBlock);
                const glm::vec2 frac = blocks - glm::floor(blocks);
                if (glm::any(glm::lessThan(frac, glm::vec2(0.1f))) || glm::any(glm::greaterThan(frac, glm::vec2(0.9f))))
                    continue;  // near a block edge: the pixel's centre may round either way
                const int parity = (int(std::floor(blocks.x)) + int(std::floor(blocks.y))) & 1;
                const LinearRgb tint = cascadeTintOf(c);
                const float brightest = std::max({tint.r, tint.g, tint.b});
                const float even = encodeSrgb(brightest), odd = encodeSrgb(0.45f * brightest);
                const glm::u8vec4 p = test::pixelAt(img, {x, y});
                const float shown = float(std::max({p.r, p.g, p.b})) / 255.0f;
                agree += (shown > 0.5f * (even + odd) ? 0 : 1) == parity;
                ++compared;
                cascades.insert(c);
                parities.insert(parity);
            }
        EXPECT_GT(compared, 10000);
        EXPECT_EQ(cascades.size(), 4u) << "every cascade is on screen";
        EXPECT_EQ(parities.size(), 2u);
        EXPECT_GE(double(agree), 0.995 * compared) << agree << " of " << compared;
    }
}

// The squares double in world size when the block doubles: the grid is in texels, not metres.
TEST_F(TexelViewsGLTest, TexelGridBlockIsCountedInTexels) {
    Scene scene = makeBuiltinScene("yard");
    Renderer r(scene);
    auto edges = [&](int blockTexels) {
        Settings s = flatLitYard(View::TexelGrid);
        s.output.texelBlock = blockTexels;
        const Rgba8Image img = test::renderImage(r, s);
        int n = 0;
        for (int x = 1; x < img.width; ++x)
            n += std::abs(int(test::pixelAt(img, {x, 170}).r) - int(test::pixelAt(img, {x - 1, 170}).r)) > 40;
        return n;
    };
    const int fine = edges(4), coarse = edges(8);
    EXPECT_GT(fine, 8);
    EXPECT_NEAR(double(fine) / double(coarse), 2.0, 0.5) << fine << " vs " << coarse << " edges along a row";
}

// Analytic: a light looking straight down on a 10 m square, 4 x 4 texels; texel centres are at
// -5 + (i + 0.5) x 2.5 m, at the height the stored depth says; a cleared texel gives no point.
TEST(TexelCloudTest, TexelsBackProjectToTheirCentres) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 10.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 proj = glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 0.0f, 20.0f);
    const glm::mat4 toTexture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    const glm::mat4 shadow = toTexture * proj * view;
    std::vector<float> depth(16, 0.5f);  // depth 0.5 of 0..20 m from y = 10: the plane y = 0
    depth[5] = 1.0f;                     // texel (1, 1) cleared
    std::vector<LineVertex> points;
    backProjectTexels(depth, {0, 0, 4, 4, 4}, shadow, 1, glm::vec3(1.0f), [](glm::vec3) { return true; }, points);
    ASSERT_EQ(points.size(), 15u);
    for (const LineVertex& v : points) {
        EXPECT_NEAR(v.position.y, 0.0f, 1e-4f);
        const float ix = (v.position.x + 5.0f) / 2.5f - 0.5f, iz = (5.0f - v.position.z) / 2.5f - 0.5f;
        EXPECT_NEAR(ix, std::round(ix), 1e-4f);  // on a texel centre
        EXPECT_NEAR(iz, std::round(iz), 1e-4f);
        EXPECT_FALSE(std::round(ix) == 1.0f && std::round(iz) == 1.0f) << "the cleared texel";
    }
    points.clear();
    backProjectTexels(depth, {0, 0, 4, 4, 4}, shadow, 2, glm::vec3(1.0f), [](glm::vec3) { return true; }, points);
    EXPECT_EQ(points.size(), 4u) << "every second texel in x and y";
    EXPECT_EQ(texelCloudStride(256), 1);
    EXPECT_EQ(texelCloudStride(4096), 12);  // ceil(4096 / 362.04)
}

// On box-over-plane every texel the side view draws lies on the ground or on the box, for every
// storage (the tile matrix folded in), and the points show in the cascades' tints.
TEST_F(TexelViewsGLTest, SideTexelsLieOnTheScene) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = test::boxOverPlaneView({0.0f, 8.0f, 12.0f}, {0.0f, 0.0f, 0.0f}, 40.0f);
    s.cascades.count = 2;
    s.cascades.mapSize = 256;
    s.output = {240, 160, View::Side};
    for (CascadeStorage storage : {CascadeStorage::Array, CascadeStorage::Atlas, CascadeStorage::Textures}) {
        SCOPED_TRACE(int(storage));
        s.cascades.storage = storage;
        s.output.sideTexels = false;
        const Rgba8Image plain = test::renderImage(r, s);
        s.output.sideTexels = true;
        const Rgba8Image texels = test::renderImage(r, s);
        const gpu_if::CascadeBlock block = cascadeBlock(s, r.plan());
        std::vector<glm::mat4> matrices{block.cascade[0].shadowMatrix, block.cascade[1].shadowMatrix};
        std::size_t onScene = 0, total = 0;
        for (const LineVertex& v : texelCloud(r.shadowMaps(), r.plan(), s.cascades.selection, matrices)) {
            const glm::vec3 p = v.position;
            const bool ground = std::abs(p.y) < 0.05f && std::abs(p.x) <= 20.05f && std::abs(p.z) <= 20.05f;
            const bool box = p.x > -1.05f && p.x < 1.05f && p.z > -1.05f && p.z < 1.05f && p.y > 1.95f && p.y < 4.05f;
            onScene += ground || box;
            ++total;
        }
        EXPECT_GT(total, 1000u);
        EXPECT_GE(double(onScene), 0.999 * double(total)) << onScene << " of " << total;
        int changed = 0, tinted = 0;
        for (int y = 0; y < plain.height; ++y)
            for (int x = 0; x < plain.width; ++x) {
                const glm::u8vec4 a = test::pixelAt(plain, {x, y}), b = test::pixelAt(texels, {x, y});
                if (a == b) continue;
                ++changed;
                for (int c = 0; c < 2; ++c) {
                    const LinearRgb t = cascadeTintOf(c);
                    tinted += std::abs(b.r - encodeSrgb(t.r) * 255.0f) < 3.0f && std::abs(b.g - encodeSrgb(t.g) * 255.0f) < 3.0f &&
                              std::abs(b.b - encodeSrgb(t.b) * 255.0f) < 3.0f;
                }
            }
        EXPECT_GT(changed, 200);
        EXPECT_GE(double(tinted), 0.98 * changed) << "changed pixels are texel points in a cascade tint";
    }
}
