// The ray-cast ground truth of a real frame against geometry worked out by hand: the shadow of
// builtin:box-over-plane's box is its eight corners moved along the light onto y = 0.
#include "renderer/csm/light_fit.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <vector>

namespace st {
namespace {

class GroundTruthGLTest : public test::GLTest {};

// Screen position (pixels, x right, y down, pixel centres at +0.5) of a world point.
glm::vec2 toScreen(const glm::mat4& viewProj, glm::vec3 ws, int width, int height) {
    const glm::vec4 cs = viewProj * glm::vec4(ws, 1.0f);
    const glm::vec2 ndc = glm::vec2(cs) / cs.w;
    return {(ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height)};
}

// Convex hull (Andrew's monotone chain), counter-clockwise in a y-down frame's orientation.
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> p) {
    std::sort(p.begin(), p.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<glm::vec2> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

// Signed distance to a convex polygon's boundary: negative inside.
float signedDistance(const std::vector<glm::vec2>& hull, glm::vec2 q) {
    float inside = -1e30f, outside = 1e30f;
    bool in = true;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        const glm::vec2 e = b - a, n = glm::normalize(glm::vec2(e.y, -e.x));
        const float side = glm::dot(q - a, n);  // > 0: outside this edge (hull is counter-clockwise)
        in = in && side <= 0.0f;
        inside = std::max(inside, side);
        const float t = std::clamp(glm::dot(q - a, e) / glm::dot(e, e), 0.0f, 1.0f);
        outside = std::min(outside, glm::length(q - (a + t * e)));
    }
    return in ? inside : outside;
}

TEST_F(GroundTruthGLTest, BoxShadowMatchesTheProjectedPolygonToOnePixel) {
    Settings s = test::presetAtTestSize("box-over-plane", 640, 360);
    metrics::MeasureSession session;
    const metrics::PresetMeasurement m = test::measureStill(session, s);
    const glm::vec3 light = csm::lightDirection(s.light.azimuth, s.light.elevation);
    std::vector<glm::vec2> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p((i & 1) ? 1.0f : -1.0f, (i & 2) ? 4.0f : 2.0f, (i & 4) ? 1.0f : -1.0f);
        corners.push_back(toScreen(metrics::observerViewProj(s), p + light * (-p.y / light.y), 640, 360));
    }
    const std::vector<glm::vec2> hull = convexHull(corners);
    int checkedInside = 0, checkedOutside = 0;
    for (int y = 0; y < 360; ++y) {
        for (int x = 0; x < 640; ++x) {
            const std::size_t i = std::size_t(y) * 640 + x;
            if (!m.samples.receiver(i) || std::abs(m.samples.position[i].y) > 1e-4f) continue;  // ground only
            const float d = signedDistance(hull, {float(x) + 0.5f, float(y) + 0.5f});
            if (std::abs(d) <= 1.0f) continue;  // within a pixel of the edge: either answer is right
            ASSERT_EQ(m.truth[i], d > 0.0f ? 1 : 0) << "pixel " << x << "," << y << " at " << d << " px from the edge";
            (d > 0.0f ? checkedOutside : checkedInside)++;
        }
    }
    EXPECT_GT(checkedInside, 800);  // the shadow spans about 1100 pixels at this size
    EXPECT_GT(checkedOutside, 100000);
}

}  // namespace
}  // namespace st
