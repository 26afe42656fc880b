// RenderOptions::subpixelSteps (engine-check's model of a rasterizer with fewer sub-pixel bits,
// SwiftShader's 4): the surfaces the measurement pass reads are interpolated from vertices snapped
// to 1/16 pixel. Held against the same interpolation worked on the CPU in double from the scene's
// own vertices (snap each to the grid, perspective-correct barycentrics at the pixel centre): the
// GPU's positions match it, and differ from the unsnapped ones by far more than that match.
#include "renderer/render/measure_pass.h"
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace st;

namespace {
class SubpixelGLTest : public test::GLTest {};

struct Snapped {
    glm::dvec2 window;  // pixels, GL's origin (bottom left)
    double w;
};

Snapped snap(const glm::dmat4& viewProj, glm::dvec3 p, int width, int height, int steps) {
    const glm::dvec4 c = viewProj * glm::dvec4(p, 1.0);
    glm::dvec2 window = (glm::dvec2(c) / c.w * 0.5 + 0.5) * glm::dvec2(width, height);
    if (steps > 0) window = glm::dvec2(std::nearbyint(window.x * steps), std::nearbyint(window.y * steps)) / double(steps);
    return {window, c.w};
}

// The world position the rasterizer interpolates at window point q over triangle (a, b, c), or
// nullopt outside it (with a margin: edge pixels may belong to the neighbour).
std::optional<glm::dvec3> interpolate(const Snapped (&s)[3], const glm::dvec3 (&p)[3], glm::dvec2 q) {
    const auto area = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); };
    const double total = area(s[0].window, s[1].window, s[2].window);
    if (std::abs(total) < 1e-9) return std::nullopt;
    const double l0 = area(q, s[1].window, s[2].window) / total;
    const double l1 = area(s[0].window, q, s[2].window) / total;
    const double l2 = 1.0 - l0 - l1;
    if (std::min({l0, l1, l2}) < 0.01) return std::nullopt;
    const double b0 = l0 / s[0].w, b1 = l1 / s[1].w, b2 = l2 / s[2].w;  // perspective-correct
    return (b0 * p[0] + b1 * p[1] + b2 * p[2]) / (b0 + b1 + b2);
}

TEST_F(SubpixelGLTest, SurfacesAreInterpolatedFromVerticesOnASixteenthPixelGrid) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    MeasurePass measure;
    Settings s = test::boxOverPlaneView({0.3f, 7.1f, 29.7f}, {0.1f, 0.0f, -3.0f}, 90.0f);
    s.cascades.count = 1;
    s.output = {173, 97, View::Shaded};  // odd sizes: the grid is the pixel's, not the NDC's
    RenderOptions o;
    o.subpixelSteps = 16;
    r.setOptions(o);
    r.render(s);
    const glm::mat4 observer = r.plan().csProj * r.plan().vsView;
    const MeasureSamples snapped = measure.run(r, s, observer);
    o.subpixelSteps = 0;
    r.setOptions(o);
    r.render(s);
    const MeasureSamples own = measure.run(r, s, observer);

    const glm::dmat4 vp(observer);
    int checked = 0, moved = 0;
    double worstSnapped = 0.0;
    for (std::size_t t = 0; t + 2 < scene.indices.size(); t += 3) {
        glm::dvec3 p[3];
        Snapped sn[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = glm::dvec3(scene.vertices[scene.indices[t + std::size_t(k)]].position);
            sn[k] = snap(vp, p[k], s.output.width, s.output.height, 16);
        }
        if (std::max({p[0].y, p[1].y, p[2].y}) > 1e-4) continue;  // the ground: all in front of the eye, hidden by the box alone
        for (int y = 0; y < s.output.height; ++y)
            for (int x = 0; x < s.output.width; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(s.output.width) + std::size_t(x);  // rows top first
                if (!snapped.covered(i) || std::abs(snapped.position[i].y) > 1e-3f) continue;     // the box's own pixels
                const auto expect = interpolate(sn, p, {x + 0.5, s.output.height - y - 0.5});
                if (!expect) continue;
                const glm::dvec3 gpu(snapped.position[i]);
                worstSnapped = std::max(worstSnapped, glm::distance(gpu, *expect) / glm::length(*expect - glm::dvec3(s.camera.position)));
                moved += glm::distance(glm::dvec3(own.position[i]), *expect) > 1e-5 * glm::length(*expect - glm::dvec3(s.camera.position));
                ++checked;
            }
    }
    EXPECT_GT(checked, 5000);
    // float32 positions: a few 1e-7 of their distance; an unsnapped vertex moves them by ~1e-4.
    EXPECT_LT(worstSnapped, 5e-6);
    EXPECT_GT(moved, checked / 2);
}

}  // namespace
