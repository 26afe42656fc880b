// Moment filters (VSM, EVSM, MSM) on llvmpipe: the maps hold the depth moments (blurred by the
// CPU's own separable Gaussian), the shaders' MSM reconstruction matches a double-precision CPU
// solve on known moments, EVSM with small exponents reads like VSM, and the costs are reported.
#include "renderer/render/measure_pass.h"
#include "renderer/render/moment_maps.h"
#include "renderer/render/shader_library.h"
#include "renderer/render/shadow_map_view.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/enum_names.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <string>
#include <vector>

using namespace st;

namespace {
class MomentsGLTest : public test::GLTest {};

Settings boxSettings(FilterKind kind) {
    Settings s = test::boxOverPlaneView({0.0f, 12.0f, 14.0f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    s.light.azimuth = 30.0f;
    s.light.elevation = 55.0f;
    s.cascades.count = 2;
    s.cascades.mapSize = 256;
    s.filter.kind = kind;
    s.output = {160, 120, View::Shadow};
    return s;
}

std::vector<float> readLayer(GLuint texture, GLenum format, int components, int size, int layer) {
    std::vector<float> out(std::size_t(size) * std::size_t(size) * std::size_t(components));
    glGetTextureSubImage(texture, 0, 0, 0, layer, size, size, 1, format, GL_FLOAT, GLsizei(out.size() * sizeof(float)),
                         out.data());
    return out;
}

// The CPU's separable Gaussian of the moment blur: sigma = (r + 1) / 2, edge texels repeated.
std::vector<double> blurRows(const std::vector<double>& v, int size, int r, bool alongX) {
    const double sigma = 0.5 * (r + 1);
    std::vector<double> w;
    double sum = 0.0;
    for (int k = -r; k <= r; ++k) sum += w.emplace_back(std::exp(-k * k / (2.0 * sigma * sigma)));
    std::vector<double> out(v.size(), 0.0);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int k = -r; k <= r; ++k) {
                const int xx = alongX ? std::clamp(x + k, 0, size - 1) : x;
                const int yy = alongX ? y : std::clamp(y + k, 0, size - 1);
                out[std::size_t(y) * size + x] += w[std::size_t(k + r)] / sum * v[std::size_t(yy) * size + xx];
            }
    return out;
}
}  // namespace

TEST_F(MomentsGLTest, VsmMapHoldsTheBlurredDepthMomentsAndRadiusZeroIsNoBlur) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    for (int radius : {0, 3}) {
        Settings s = boxSettings(FilterKind::Vsm);
        s.filter.blurRadius = radius;
        r.render(s);
        const int n = 256;
        const auto depth = readLayer(r.shadowMapTexture(), GL_DEPTH_COMPONENT, 1, n, 1);
        const auto moments = readLayer(r.momentMaps().texture(), GL_RG, 2, n, 1);
        std::vector<double> z(depth.begin(), depth.end()), z2(depth.size());
        for (std::size_t i = 0; i < z.size(); ++i) z2[i] = z[i] * z[i];
        const auto m1 = blurRows(blurRows(z, n, radius, true), n, radius, false);
        const auto m2 = blurRows(blurRows(z2, n, radius, true), n, radius, false);
        double worst = 0.0;
        int edges = 0;  // texels whose moments a blur changes: there must be some at radius 3
        for (std::size_t i = 0; i < z.size(); ++i) {
            worst = std::max({worst, std::abs(moments[2 * i] - m1[i]), std::abs(moments[2 * i + 1] - m2[i])});
            edges += std::abs(m1[i] - z[i]) > 1e-3;
        }
        if (radius == 0) {
            EXPECT_EQ(edges, 0);
            for (std::size_t i = 0; i < z.size(); ++i) ASSERT_EQ(moments[2 * i], depth[i]) << "texel " << i;
        } else {
            EXPECT_GT(edges, 100);
        }
        EXPECT_LT(worst, 2e-6) << "radius " << radius;
    }
}

TEST_F(MomentsGLTest, EveryMomentFilterShadowsTheBoxAndLightsThePlane) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    for (FilterKind k : {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm})
        for (bool sixteen : {false, true}) {
            Settings s = boxSettings(k);
            s.filter.moments16 = sixteen;
            s.filter.mipmaps = sixteen;
            const Rgba8Image img = test::renderImage(r, s);
            // Under the box's centre (the light travels down through y=3 at the origin) and far
            // beside it on the plane.
            const glm::vec3 dir = r.plan().wsLightDir;
            const auto under = test::projectToPixel(r, glm::vec3(0.0f, 3.0f, 0.0f) + dir * (-3.0f / dir.y));
            const auto beside = test::projectToPixel(r, glm::vec3(-6.0f, 0.0f, 4.0f));
            ASSERT_TRUE(under && beside);
            // sRGB 80 is 8 % of the light: Chebyshev's bound is an upper bound, never quite 0.
            EXPECT_LT(test::pixelAt(img, *under).r, 80) << enumName(k) << " 16-bit " << sixteen;
            EXPECT_GT(test::pixelAt(img, *beside).r, 200) << enumName(k) << " 16-bit " << sixteen;
        }
}

// Chebyshev's bound is invariant under an affine map of depth, and exp(c x) is affine to first
// order in c: with c = 0.05 EVSM's positive bound is VSM's (the variance floor scales along).
TEST_F(MomentsGLTest, EvsmWithSmallExponentsIsCloseToVsm) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = boxSettings(FilterKind::Vsm);
    s.filter.blurRadius = 3;
    const Rgba8Image vsm = test::renderImage(r, s);
    s.filter.kind = FilterKind::Evsm2;
    s.filter.evsmPositive = 0.05f;
    const Rgba8Image evsm = test::renderImage(r, s);
    s.filter.evsmPositive = 40.0f;
    const Rgba8Image steep = test::renderImage(r, s);
    double near = 0.0, far = 0.0;
    int soft = 0;
    for (std::size_t i = 0; i < vsm.pixels.size(); i += 4) {
        near += std::abs(int(vsm.pixels[i]) - int(evsm.pixels[i]));
        far += std::abs(int(vsm.pixels[i]) - int(steep.pixels[i]));
        soft += vsm.pixels[i] > 10 && vsm.pixels[i] < 245;
    }
    const double pixels = double(vsm.pixels.size() / 4);
    EXPECT_GT(soft, 100);              // there is a penumbra to compare
    EXPECT_LT(near / pixels, 0.5);     // mean |difference| in 8-bit levels
    EXPECT_GT(far / pixels, 2.0 * near / pixels + 0.05);  // and a steep warp does differ
}

TEST_F(MomentsGLTest, FilterCostsAreReported) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = boxSettings(FilterKind::Evsm4);
    FrameStats stats = r.render(s);
    // 2 layers of 256^2 RGBA32F, plus the 256^2 RGBA32F scratch texture.
    EXPECT_EQ(stats.filterMapBytes, 2u * 256u * 256u * 16u + 256u * 256u * 16u);
    EXPECT_GT(stats.gpuFilterMs, 0.0);
    s.filter.kind = FilterKind::Vsm;
    s.filter.moments16 = true;
    s.filter.mipmaps = true;
    stats = r.render(s);
    std::size_t mips = 0;
    for (int n = 256; n >= 1; n /= 2) mips += std::size_t(n) * std::size_t(n);
    EXPECT_EQ(stats.filterMapBytes, 2u * mips * 4u + 256u * 256u * 16u);
    s.filter.kind = FilterKind::Pcf2x2;
    stats = r.render(s);
    EXPECT_EQ(stats.filterMapBytes, 0u);
    EXPECT_EQ(stats.gpuFilterMs, 0.0);
}

// ---- MSM: the shader's Hamburger reconstruction against a CPU solve in double ------------------
namespace {
struct MsmCase {
    std::array<double, 4> b;
    double zf;
};

// Independent of the shader's Cholesky steps: B c = (1, zf, zf^2) by Cramer's rule, the roots of
// c0 + c1 z + c2 z^2, then the weights of the three atoms (zf, z2, z3) matching (1, b1, b2) by
// solving their Vandermonde system; the shadow intensity is the weight of the atoms in front of zf.
double msmReference(const std::array<double, 4>& b, double zf) {
    const double B[3][3] = {{1, b[0], b[1]}, {b[0], b[1], b[2]}, {b[1], b[2], b[3]}};
    auto det3 = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double rhs[3] = {1, zf, zf * zf};
    double c[3];
    for (int col = 0; col < 3; ++col) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == col ? rhs[i] : B[i][j];
        c[col] = det3(m) / det3(B);
    }
    const double disc = std::sqrt(std::max(c[1] * c[1] - 4 * c[2] * c[0], 0.0));
    const double z2 = std::min((-c[1] - disc) / (2 * c[2]), (-c[1] + disc) / (2 * c[2]));
    const double z3 = std::max((-c[1] - disc) / (2 * c[2]), (-c[1] + disc) / (2 * c[2]));
    // Weights w of atoms a = (zf, z2, z3): sum w = 1, sum w a = b1, sum w a^2 = b2.
    const double a[3] = {zf, z2, z3};
    const double V[3][3] = {{1, 1, 1}, {a[0], a[1], a[2]}, {a[0] * a[0], a[1] * a[1], a[2] * a[2]}};
    const double m0[3] = {1, b[0], b[1]};
    double w[3];
    for (int col = 0; col < 3; ++col) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == col ? m0[i] : V[i][j];
        w[col] = det3(m) / det3(V);
    }
    double g = 0.0;
    for (int k = 1; k < 3; ++k) g += a[k] < zf ? w[k] : 0.0;
    return std::clamp(g, 0.0, 1.0);
}

std::array<double, 4> momentsOfAtoms(std::initializer_list<std::pair<double, double>> atoms) {
    std::array<double, 4> b{};
    for (auto [z, w] : atoms)
        for (int k = 0; k < 4; ++k) b[std::size_t(k)] += w * std::pow(z, k + 1);
    return b;
}
}  // namespace

TEST_F(MomentsGLTest, MsmReconstructionMatchesTheCpuReference) {
    std::vector<MsmCase> cases;
    const auto three = momentsOfAtoms({{0.2, 0.3}, {0.5, 0.3}, {0.8, 0.4}});
    const auto wide = momentsOfAtoms({{0.1, 0.5}, {0.3, 0.2}, {0.6, 0.2}, {0.9, 0.1}});
    for (double zf : {0.05, 0.25, 0.45, 0.55, 0.7, 0.85, 0.95}) {
        cases.push_back({three, zf});
        cases.push_back({wide, zf});
    }
    std::string consts = "const vec4 kB[] = vec4[](";
    std::string zs = "const float kZ[] = float[](";
    for (std::size_t i = 0; i < cases.size(); ++i) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%svec4(%.9g, %.9g, %.9g, %.9g)", i ? ", " : "", cases[i].b[0], cases[i].b[1],
                      cases[i].b[2], cases[i].b[3]);
        consts += buf;
        std::snprintf(buf, sizeof buf, "%s%.9g", i ? ", " : "", cases[i].zf);
        zs += buf;
    }
    ShaderSources sources = embeddedShaders();
    sources["msm_probe.frag"] = "#version 450 core\n#include \"moments.glsl\"\n" + consts + ");\n" + zs +
                                ");\nout vec4 o;\nvoid main() { int i = int(gl_FragCoord.x);\n"
                                "  o = vec4(msmShadowIntensity(kB[i], kZ[i]), 0.0, 0.0, 1.0); }\n";
    gpu::Program program = linkShaderFiles("fullscreen.vert", "msm_probe.frag", "msm_probe", sources);
    const int n = int(cases.size());
    gpu::Texture target = gpu::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(target.id(), 1, GL_RGBA32F, n, 1);
    gpu::Framebuffer fbo = gpu::createFramebuffer();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    gpu::VertexArray vao = gpu::createVertexArray();
    gpu::PassState state;
    state.framebuffer = fbo.id();
    state.viewport = {0, 0, n, 1};
    gpu::applyPassState(state);
    glUseProgram(program.id());
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> out(std::size_t(n) * 4);
    glGetTextureImage(target.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
    for (int i = 0; i < n; ++i) {
        const double want = msmReference(cases[std::size_t(i)].b, cases[std::size_t(i)].zf);
        EXPECT_NEAR(out[std::size_t(i) * 4], want, 2e-3) << "case " << i << " zf " << cases[std::size_t(i)].zf;
    }
    // Known answers: in front of every atom nothing occludes; behind all of them nearly all does.
    EXPECT_NEAR(out[0], 0.0, 1e-6);
    EXPECT_GT(out[std::size_t(n - 2) * 4], 0.7);
}

// The shadow-map viewer's moment tiles (issue 12: "first moment as depth, variance as a second
// image"): with a tile as large as the map, tile pixel (x, y) shows texel (x, y). Its expected
// colours come from the depth layer alone, blurred on the CPU (blurRows): the mean tile the grey
// ramp of the blurred depth over the tile's range (depth_view.frag's ramp), the spread tile
// 16 sqrt(E z^2 - (E z)^2) / span as yellow. VSM and MSM store E z and E z^2 directly.
TEST_F(MomentsGLTest, ViewerMomentTilesShowTheMeanAndTheSpreadOfTheDepths) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Msm}) {
        SCOPED_TRACE(enumName(kind));
        Settings s = boxSettings(kind);
        s.filter.blurRadius = 2;
        r.render(s);
        const int n = 256, layer = 0;
        ShadowMapView view;
        view.update(r.shadowMaps(), n, &r.momentMaps());
        ASSERT_NE(view.varianceTexture(layer), 0u);
        const auto depth = readLayer(r.shadowMapTexture(), GL_DEPTH_COMPONENT, 1, n, layer);
        std::vector<double> z(depth.begin(), depth.end()), z2(depth.size());
        for (std::size_t i = 0; i < z.size(); ++i) z2[i] = z[i] * z[i];
        const auto m1 = blurRows(blurRows(z, n, 2, true), n, 2, false);
        const auto m2 = blurRows(blurRows(z2, n, 2, true), n, 2, false);
        std::vector<std::uint8_t> mean(std::size_t(n) * n * 4), spread(mean.size());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTextureImage(view.layerTexture(layer), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(mean.size()), mean.data());
        glGetTextureImage(view.varianceTexture(layer), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(spread.size()),
                          spread.data());
        const auto [lo, hi] = view.depthRange(layer);
        const double span = std::max(double(hi) - double(lo), 1e-6);
        int worstMean = 0, worstSpread = 0, spreadTexels = 0;
        for (std::size_t i = 0; i < z.size(); ++i) {
            if (m1[i] >= 0.9999) continue;  // never written: the blue of depth_view.frag
            const double v = 1.0 - std::clamp((m1[i] - lo) / span, 0.0, 1.0);
            worstMean = std::max(worstMean, std::abs(int(mean[4 * i]) - int(std::lround(255.0 * (0.15 + 0.85 * v)))));
            const double sd = std::sqrt(std::max(m2[i] - m1[i] * m1[i], 0.0));
            const double y = std::clamp(16.0 * sd / span, 0.0, 1.0);
            // Where the variance is a float rounding of E z^2 - (E z)^2 (flat texels), 2 levels.
            worstSpread = std::max(worstSpread, std::abs(int(spread[4 * i]) - int(std::lround(255.0 * y))));
            spreadTexels += spread[4 * i] > 100;
        }
        EXPECT_LE(worstMean, 2) << "mean tile: grey levels from the CPU's blurred depth";
        EXPECT_LE(worstSpread, 3) << "spread tile: levels from the CPU's blurred depth";
        EXPECT_GT(spreadTexels, 50) << "the box's outline: two depths in the blur, a bright spread";
        std::printf("[ figures  ] %s tiles: worst mean %d, spread %d levels; %d texels of bright spread\n",
                    enumName(kind).data(), worstMean, worstSpread, spreadTexels);
        // No blur: each texel holds one depth, z^2 - z^2 = 0, and the spread tile is black.
        s.filter.blurRadius = 0;
        r.render(s);
        view.update(r.shadowMaps(), n, &r.momentMaps());
        glGetTextureImage(view.varianceTexture(layer), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(spread.size()),
                          spread.data());
        int lit = 0;
        for (std::size_t i = 0; i < spread.size(); i += 4) lit += spread[i] != 0;
        EXPECT_EQ(lit, 0) << "no spread without a blur";
    }
}

namespace {
// The bleed remap (filter.bleedLow/High, three.js's (p - 0.3) / 0.65) against the CPU's own remap
// of the unremapped factor, pixel by pixel: the measurement pass's float factors, not the image.
TEST_F(MomentsGLTest, BleedRemapIsTheLinstepOfTheUnremappedShare) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    MeasurePass measure;
    Settings s = boxSettings(FilterKind::Vsm);
    s.filter.blurRadius = 3;
    r.render(s);
    const glm::mat4 observer = r.plan().csProj * r.plan().vsView;
    const MeasureSamples plain = measure.run(r, s, observer);
    s.filter.bleedLow = 0.3f;
    s.filter.bleedHigh = 0.95f;
    r.render(s);
    const MeasureSamples remapped = measure.run(r, s, observer);
    int partial = 0, cut = 0;
    for (std::size_t i = 0; i < plain.size(); ++i) {
        if (!plain.receiver(i)) continue;
        const float p = plain.shadow[i].y;
        const float want = std::clamp((p - 0.3f) / 0.65f, 0.0f, 1.0f);
        ASSERT_NEAR(remapped.shadow[i].y, want, 2e-5f) << "pixel " << i << ", unremapped " << p;
        partial += p > 0.01f && p < 0.99f;
        cut += p > 0.01f && p < 0.3f;
    }
    EXPECT_GT(partial, 100);  // penumbrae to remap
    EXPECT_GT(cut, 10);       // some of them cut to full shadow
}
}  // namespace
