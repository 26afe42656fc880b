#include "renderer/csm/frustum.h"
#include "renderer/csm/selection.h"
#include "renderer/csm/splits.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace st::csm {
namespace {

// The shader's selectInterval: vsDepth <= splits[i+1] picks i, no lower bound.
TEST(SelectionTest, IntervalAtBoundariesAndOutside) {
    const std::vector<float> z = {1.0f, 10.0f, 50.0f, 200.0f};
    EXPECT_EQ(selectCascadeInterval(z, 0.5f), 0);  // nearer than the near split: still cascade 0
    EXPECT_EQ(selectCascadeInterval(z, -3.0f), 0);
    EXPECT_EQ(selectCascadeInterval(z, 1.0f), 0);
    EXPECT_EQ(selectCascadeInterval(z, 9.999f), 0);
    EXPECT_EQ(selectCascadeInterval(z, 10.0f), 0);  // a split belongs to the cascade it ends
    EXPECT_EQ(selectCascadeInterval(z, std::nextafter(10.0f, 11.0f)), 1);
    EXPECT_EQ(selectCascadeInterval(z, 49.9f), 1);
    EXPECT_EQ(selectCascadeInterval(z, 50.0f), 1);
    EXPECT_EQ(selectCascadeInterval(z, std::nextafter(50.0f, 51.0f)), 2);
    EXPECT_EQ(selectCascadeInterval(z, 200.0f), 2);  // the last end is still shadowed
    EXPECT_EQ(selectCascadeInterval(z, std::nextafter(200.0f, 201.0f)), -1);
    EXPECT_EQ(selectCascadeInterval(z, std::numeric_limits<float>::quiet_NaN()), -1);
    EXPECT_EQ(selectCascadeInterval(std::vector<float>{1.0f, 5.0f}, 5.0f), 0);  // one cascade
    EXPECT_THROW(selectCascadeInterval(std::vector<float>{1.0f}, 1.0f), std::invalid_argument);
}

FilterSettings filter(FilterKind kind, int size = 3) {
    FilterSettings f;
    f.kind = kind;
    f.size = size;
    return f;
}

TEST(SelectionTest, EdgeMarginIsTheFilterRadiusPlusOneTexel) {
    EXPECT_FLOAT_EQ(mapEdgeMargin(filter(FilterKind::Hard, 5), 1024), 1.0f / 1024.0f);
    EXPECT_FLOAT_EQ(mapEdgeMargin(filter(FilterKind::Pcf2x2, 5), 512), 1.0f / 512.0f);
    EXPECT_FLOAT_EQ(mapEdgeMargin(filter(FilterKind::PcfNxN, 5), 1024), 3.0f / 1024.0f);  // 2 taps + 1
    EXPECT_FLOAT_EQ(mapEdgeMargin(filter(FilterKind::PcfNxN, 3), 256), 2.0f / 256.0f);
    // PCSS: its kernel and blocker search reach up to the capped radius (7.5 -> 8), + 1.
    FilterSettings pcss = filter(FilterKind::Pcss, 5);
    pcss.pcssMaxRadius = 7.5f;
    EXPECT_FLOAT_EQ(mapEdgeMarginTexels(pcss), 9.0f);
    // Moment filters: the blur gathered each texel's moments from blurRadius texels, + 1.
    for (FilterKind k : {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm}) {
        FilterSettings m = filter(k);
        m.blurRadius = 4;
        EXPECT_FLOAT_EQ(mapEdgeMarginTexels(m), 5.0f) << int(k);
        m.blurRadius = 0;
        EXPECT_FLOAT_EQ(mapEdgeMarginTexels(m), 1.0f) << int(k);
    }
}

struct Fitted {
    CameraParams cam;
    std::vector<float> splits;
    std::vector<CascadeFit> fits;
};

Fitted fitted(FitMode mode) {
    Fitted f;
    SplitParams s;
    s.nearPlane = f.cam.nearPlane;
    s.farPlane = f.cam.farPlane;
    f.splits = computeSplits(s);
    FitParams p;
    p.fit = mode;
    for (int i = 0; i < 4; ++i)
        f.fits.push_back(fitCascade(f.cam, f.splits, i, lightDirection(35.0f, 40.0f), p));
    return f;
}

TEST(SelectionTest, MapPicksCascade0NearTheCameraAndNoneFarOutside) {
    const Fitted f = fitted(FitMode::Cascade);
    const glm::vec3 forward = glm::normalize(f.cam.wsTarget - f.cam.wsPosition);
    EXPECT_EQ(selectCascadeMap(f.fits, f.cam.wsPosition + 1.0f * forward), 0);
    EXPECT_EQ(selectCascadeMap(f.fits, f.cam.wsPosition + 5000.0f * forward), -1);
    EXPECT_EQ(selectCascadeMap(f.fits, glm::vec3(1e5f, 0.0f, 0.0f)), -1);
}

TEST(SelectionTest, MapNeverPicksALaterCascadeThanInterval) {
    // Each box holds its own slice, so the first box that holds a point is at most the point's
    // interval cascade (seed 004: map selection can pick a finer cascade, never a coarser one).
    const Fitted f = fitted(FitMode::Cascade);
    const glm::mat4 wsFromVs = inverseViewMatrix(f.cam);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float ty = std::tan(0.5f * f.cam.fovY);
    for (int trial = 0; trial < 500; ++trial) {
        const float d = f.splits.front() + (f.splits.back() - f.splits.front()) * u(rng) * u(rng);
        const glm::vec3 vs((2 * u(rng) - 1) * d * ty * f.cam.aspect, (2 * u(rng) - 1) * d * ty, -d);
        const glm::vec3 ws(wsFromVs * glm::vec4(vs, 1.0f));
        const int interval = selectCascadeInterval(f.splits, d);
        const int map = selectCascadeMap(f.fits, ws);
        ASSERT_GE(interval, 0);
        EXPECT_GE(map, 0) << "depth " << d;
        EXPECT_LE(map, interval) << "depth " << d;
    }
}

TEST(SelectionTest, MapMarginExcludesTheBorder) {
    const Fitted f = fitted(FitMode::Sphere);
    // A point on cascade 0's min-x face (ts x = 0): inside with no margin, outside with one.
    const CascadeFit& c0 = f.fits[0];
    const glm::vec3 lsPoint(c0.lsBox.min.x, c0.lsBox.center().y, c0.lsBox.center().z);
    const glm::vec3 ws = glm::transpose(glm::mat3(c0.lsView)) * lsPoint;
    const std::vector<CascadeFit> only0 = {c0};
    EXPECT_EQ(selectCascadeMap(only0, ws + glm::transpose(glm::mat3(c0.lsView)) *
                                               glm::vec3(1e-3f, 0, 0)),
              0);
    EXPECT_EQ(selectCascadeMap(only0, ws, 0.01f), -1);
}

// A point 4 texels inside cascade 0's tile, on a side where cascade 1 holds it too: 2x2 PCF
// (margin 1) and a 3-texel blur (margin 4, the kernel just inside) keep cascade 0; PCSS capped at 8
// texels and a 5-texel blur would read past the tile, so the next map is picked.
TEST(SelectionTest, MapSelectionTakesTheNextMapWhereTheKernelReachesOutOfTheTile) {
    const Fitted f = fitted(FitMode::Sphere);
    const CascadeFit& c0 = f.fits[0];
    const glm::mat3 wsFromLs = glm::transpose(glm::mat3(c0.lsView));
    const float inset = 4.01f * c0.texelWorldSize;
    glm::vec3 ws{};
    bool found = false;
    for (const glm::vec2 side : {glm::vec2(-1, 0), glm::vec2(1, 0), glm::vec2(0, -1), glm::vec2(0, 1)}) {
        const glm::vec3 c = c0.lsBox.center(), h = 0.5f * c0.lsBox.extent();
        const glm::vec3 ls(c.x + side.x * (h.x - inset), c.y + side.y * (h.y - inset), c.z);
        ws = wsFromLs * ls;
        const std::vector<CascadeFit> only1 = {f.fits[1]};
        if (selectCascadeMapPerSize(only1, ws, 40.0f) == 0) {  // well inside cascade 1
            found = true;
            break;
        }
    }
    ASSERT_TRUE(found) << "cascade 1 should hold some side of cascade 0";
    auto pick = [&](const FilterSettings& fs) { return selectCascadeMapPerSize(f.fits, ws, mapEdgeMarginTexels(fs)); };
    EXPECT_EQ(pick(filter(FilterKind::Pcf2x2)), 0);
    FilterSettings pcss = filter(FilterKind::Pcss);
    pcss.pcssMaxRadius = 8.0f;
    EXPECT_EQ(pick(pcss), 1);
    pcss.pcssMaxRadius = 2.0f;
    EXPECT_EQ(pick(pcss), 0);
    FilterSettings vsm = filter(FilterKind::Vsm);
    vsm.blurRadius = 3;
    EXPECT_EQ(pick(vsm), 0);
    vsm.blurRadius = 5;
    EXPECT_EQ(pick(vsm), 1);
}

TEST(SelectionTest, MapNormalOffsetIsScaledByEachCascadesTexel) {
    const Fitted f = fitted(FitMode::Sphere);
    const CascadeFit& c0 = f.fits[0];
    const glm::mat3 wsFromLs = glm::transpose(glm::mat3(c0.lsView));
    // Just inside cascade 0's min-x face; the "normal" points out of the box along -x (ls).
    const glm::vec3 ws = wsFromLs * glm::vec3(c0.lsBox.min.x + 0.5f * c0.texelWorldSize, c0.lsBox.center().y,
                                              c0.lsBox.center().z);
    const glm::vec3 outward = wsFromLs * glm::vec3(-1.0f, 0.0f, 0.0f);
    const std::vector<CascadeFit> only0 = {c0};
    EXPECT_EQ(selectCascadeMap(only0, ws, 0.0f, outward, 0.25f), 0);  // moved a quarter texel: inside
    EXPECT_EQ(selectCascadeMap(only0, ws, 0.0f, outward, 1.0f), -1);  // a whole texel: outside
    EXPECT_EQ(selectCascadeMap(only0, ws, 0.0f, -outward, 1.0f), 0);
}

}  // namespace
}  // namespace st::csm
