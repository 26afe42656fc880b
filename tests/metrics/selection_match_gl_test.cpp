// The CPU cascade selection (renderer/csm/selection) is the shader's (shadow_sampling.glsl): on
// every pixel the measurement pass draws, the cascade the GPU picked (MeasureSamples shadow.z) is
// the one the CPU picks from the pixel's world position, for interval and map selection. Only
// pixels whose CPU-computed depth or texture coordinate lies within float rounding of a boundary
// may differ, and they must be rare.
#include "renderer/csm/cascade_plan.h"
#include "renderer/csm/conventions.h"
#include "renderer/csm/selection.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace st {
namespace {

// Float rounding of the interpolated depth: the GPU interpolates the vertices' view depth, the CPU
// recomputes it from the interpolated position. Measured on llvmpipe (default preset, 320x180):
// 6 pixels differ, all 1.2e-6 (relative) from a split; map-based coordinates matched exactly.
// 4e-6 leaves room for other drivers and stays far below one pixel row's depth step.
constexpr float kRelativeEpsilon = 4e-6f;
// Pixels allowed that close to a boundary. Not 0.1 %: with no camera roll a row of ground pixels
// has one depth, and in the default preset row 91 (235 covered pixels, 0.6 %) lies 1e-6 from
// split 1. More than a couple of rows would mean the epsilon hides a real disagreement.
constexpr double kMaxNearBoundaryShare = 0.01;

struct Match {
    std::size_t compared = 0;
    std::size_t nearBoundary = 0;  // within epsilon of a split or tile edge: may differ
    std::size_t mismatched = 0;    // elsewhere: must not
    std::string firstMismatch;
};

bool nearSplit(const std::vector<float>& splits, float depth) {
    for (float z : splits)
        if (std::fabs(depth - z) <= kRelativeEpsilon * std::fabs(z)) return true;
    return false;
}

// Any cascade's coordinate within epsilon of what selectMap compares it with.
bool nearTileEdge(const csm::CascadePlan& plan, glm::vec3 ws, glm::vec3 n, float offsetTexels, float marginTexels) {
    for (const csm::CascadeFit& c : plan.cascades) {
        const float margin = marginTexels / float(c.mapSize);  // its own map's texels
        const glm::vec3 p = ws + n * (offsetTexels * c.texelWorldSize);
        const glm::vec4 ts = csm::clipToTexture() * c.viewProj * glm::vec4(p, 1.0f);
        for (float v : {ts.x, ts.y})
            if (std::fabs(v - margin) <= kRelativeEpsilon || std::fabs(v - (1.0f - margin)) <= kRelativeEpsilon)
                return true;
        if (std::fabs(ts.z) <= kRelativeEpsilon || std::fabs(ts.z - 1.0f) <= kRelativeEpsilon) return true;
    }
    return false;
}

class SelectionMatchGLTest : public test::GLTest {
protected:
    // Renders `s` and compares the GPU's cascade with the CPU selection on every covered pixel.
    Match compare(const Settings& s) {
        auto& e = session_.entryFor(s, ST_PRESET_DIR);
        const MeasureSamples m = metrics::sampleFrame(*e.renderer, session_.pass(), s, s);
        const csm::CascadePlan& plan = e.renderer->plan();
        const float margin = csm::mapEdgeMarginTexels(s.filter);
        Match r;
        for (std::size_t i = 0; i < m.size(); ++i) {
            if (!m.covered(i)) continue;
            const glm::vec3 ws(m.position[i]), n(m.normal[i]);
            const float depth = -(plan.vsView * glm::vec4(ws, 1.0f)).z;
            const bool interval = s.cascades.selection == Selection::Interval;
            const int cpu = interval ? csm::selectCascadeInterval(plan.splits, depth)
                                     : csm::selectCascadeMapPerSize(plan.cascades, ws, margin, n, s.bias.normalOffset);
            const bool near = interval ? nearSplit(plan.splits, depth)
                                       : nearTileEdge(plan, ws, n, s.bias.normalOffset, margin);
            ++r.compared;
            r.nearBoundary += near;
            if (cpu == m.cascade(i) || near) continue;
            if (r.mismatched++ == 0) {
                std::ostringstream text;
                text << "pixel " << i % std::size_t(m.width) << "," << i / std::size_t(m.width) << " depth " << depth
                     << ": GPU " << m.cascade(i) << ", CPU " << cpu;
                r.firstMismatch = text.str();
            }
        }
        return r;
    }
    void expectMatch(const Settings& s) {
        const Match r = compare(s);
        EXPECT_GT(r.compared, 40000u);
        EXPECT_EQ(r.mismatched, 0u) << r.firstMismatch;
        EXPECT_LT(double(r.nearBoundary), kMaxNearBoundaryShare * double(r.compared))
            << r.nearBoundary << " of " << r.compared << " pixels at a boundary";
    }
    metrics::MeasureSession session_;
};

TEST_F(SelectionMatchGLTest, IntervalSelectionIsTheShaders) {
    const Settings s = test::presetAtTestSize("default");
    ASSERT_EQ(s.cascades.selection, Selection::Interval);
    expectMatch(s);
}

TEST_F(SelectionMatchGLTest, MapSelectionIsTheShadersWithMarginAndNormalOffset) {
    Settings s = test::presetAtTestSize("default");
    s.cascades.selection = Selection::Map;
    expectMatch(s);                     // 2x2 PCF: a one-texel margin
    s.filter.kind = FilterKind::PcfNxN;  // a wider margin ...
    s.filter.size = 7;
    s.bias.normalOffset = 1.5f;          // ... and each cascade moves the point by its own texel
    expectMatch(s);
    s.bias.normalOffset = 0.0f;
    s.filter.kind = FilterKind::Pcss;    // PCSS's capped kernel: a margin of 13 texels
    s.filter.pcssMaxRadius = 12.0f;
    expectMatch(s);
    s.filter.kind = FilterKind::Vsm;     // the moment blur's reach: 7 texels
    s.filter.blurRadius = 6;
    expectMatch(s);
}

// The atlas (tile bounds in the atlas's uv, each its own margin) and one texture per cascade, with
// a size per cascade: the GPU picks the cascade the CPU's tile-space rule picks.
TEST_F(SelectionMatchGLTest, MapSelectionByTileBoundsWithSizesPerCascade) {
    Settings s = test::presetAtTestSize("default");
    s.cascades.selection = Selection::Map;
    s.cascades.mapSizes = {1024, 512, 512, 256};
    s.filter.kind = FilterKind::PcfNxN;
    s.filter.size = 5;
    for (CascadeStorage storage : {CascadeStorage::Atlas, CascadeStorage::Textures}) {
        SCOPED_TRACE(int(storage));
        s.cascades.storage = storage;
        expectMatch(s);
    }
}

// The fronto-parallel case, where the interpolated depth is exact: box-over-plane from straight
// above (view depth 10 - y), with manual splits at exactly the box top's depth (6) and the
// plane's (10). A depth equal to split i+1 belongs to cascade i on both sides.
TEST_F(SelectionMatchGLTest, SurfacesAtExactSplitDepthsBelongToTheNearerCascade) {
    Settings s;
    s.scene = "builtin:box-over-plane";
    s.camera = {.position = {0.0f, 10.0f, 0.0f}, .target = {0.0f, 0.0f, 0.0f}, .fovY = 60.0f, .nearPlane = 0.1f,
                .farPlane = 100.0f};
    s.cascades.count = 3;
    s.cascades.scheme = SplitScheme::Manual;
    s.cascades.manualSplits = {6.0f, 10.0f};
    s.output.width = 320;
    s.output.height = 180;
    auto& e = session_.entryFor(s, ST_PRESET_DIR);
    const MeasureSamples m = metrics::sampleFrame(*e.renderer, session_.pass(), s, s);
    const csm::CascadePlan& plan = e.renderer->plan();
    ASSERT_EQ(plan.splits, (std::vector<float>{0.1f, 6.0f, 10.0f, 100.0f}));
    std::size_t plane = 0, top = 0;
    for (std::size_t i = 0; i < m.size(); ++i) {
        if (!m.covered(i)) continue;
        const glm::vec3 ws(m.position[i]);
        const float depth = -(plan.vsView * glm::vec4(ws, 1.0f)).z;
        const int expected = ws.y == 0.0f ? 1 : ws.y == 4.0f ? 0 : -2;  // plane: split 2; box top: split 1
        if (expected == -2) continue;
        ASSERT_EQ(depth, ws.y == 0.0f ? 10.0f : 6.0f) << "not exactly at the split: the case tests nothing";
        ASSERT_EQ(m.cascade(i), expected) << "GPU, pixel " << i % std::size_t(m.width) << "," << i / std::size_t(m.width);
        ASSERT_EQ(csm::selectCascadeInterval(plan.splits, depth), expected) << "CPU at depth " << depth;
        ++(expected == 1 ? plane : top);
    }
    EXPECT_GT(plane, 20000u);
    EXPECT_GT(top, 500u);
}

}  // namespace
}  // namespace st
