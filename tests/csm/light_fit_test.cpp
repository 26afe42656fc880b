#include "renderer/csm/frustum.h"
#include "renderer/csm/light_fit.h"
#include "renderer/csm/splits.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::csm {
namespace {

std::vector<float> splitsFor(const CameraParams& c, int count) {
    SplitParams p;
    p.count = count;
    p.nearPlane = c.nearPlane;
    p.farPlane = c.farPlane;
    return computeSplits(p);
}

std::vector<CameraParams> cameras() {
    CameraParams a;  // defaults: from +Z toward the origin, 0.1..400
    CameraParams b;
    b.wsPosition = {-40, 15, 25};
    b.wsTarget = {10, 0, -30};
    b.fovY = 0.8f;
    b.aspect = 1.0f;
    b.nearPlane = 0.5f;
    b.farPlane = 150.0f;
    CameraParams down = a;  // looking straight down
    down.wsPosition = {5, 60, 5};
    down.wsTarget = {5, 0, 5};
    return {a, b, down};
}

std::vector<glm::vec3> lightDirs() {
    return {glm::vec3(0, -1, 0),       glm::vec3(0, 1, 0),       lightDirection(35, 40),
            lightDirection(200, 10),   lightDirection(-70, 75),  glm::vec3(0.01f, -1, 0),
            glm::normalize(glm::vec3(1, -0.2f, 0.3f))};
}

bool finite(const glm::mat4& m) {
    const float* v = glm::value_ptr(m);
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

void expectCornersInside(const CascadeFit& fit, const CameraParams& cam, const std::string& what) {
    for (const glm::vec3& ws : sliceCornersFromCamera(cam, fit.vsNear, fit.vsFar)) {
        const glm::vec3 ls(fit.lsView * glm::vec4(ws, 1.0f));
        const float eps = 1e-5f * glm::length(fit.lsBox.extent()) + 1e-4f;
        EXPECT_TRUE(fit.lsBox.contains(ls, eps)) << what;
        // And through the matrices the renderer uploads: inside the light's clip cube.
        const glm::vec4 cs = fit.viewProj * glm::vec4(ws, 1.0f);
        EXPECT_TRUE(std::abs(cs.x) <= 1.0001f && std::abs(cs.y) <= 1.0001f &&
                    std::abs(cs.z) <= 1.0001f)
            << what << " cs " << cs.x << " " << cs.y << " " << cs.z;
    }
}

TEST(LightFitTest, EverySliceCornerIsInsideItsLightBox) {
    const FitMode modes[] = {FitMode::Cascade, FitMode::Scene, FitMode::Sphere};
    const ZExtension zs[] = {ZExtension::None, ZExtension::Distance, ZExtension::SceneBounds,
                             ZExtension::Pancake};
    for (const CameraParams& cam : cameras()) {
        const std::vector<float> splits = splitsFor(cam, 4);
        for (const glm::vec3& dir : lightDirs())
            for (FitMode mode : modes)
                for (int stabilize = 0; stabilize < 2; ++stabilize)
                    for (ZExtension z : zs)
                        for (int i = 0; i < 4; ++i) {
                            FitParams p;
                            p.fit = mode;
                            p.stabilize = stabilize == 1;
                            p.zExtension = z;
                            p.zExtensionDistance = 50.0f;
                            p.wsSceneBounds = {{-20, 0, -20}, {20, 10, 20}};
                            const CascadeFit fit = fitCascade(cam, splits, i, dir, p);
                            expectCornersInside(fit, cam,
                                                "mode " + std::to_string(int(mode)) + " stab " +
                                                    std::to_string(stabilize) + " cascade " +
                                                    std::to_string(i));
                        }
    }
}

TEST(LightFitTest, SceneBoundsZRangeHoldsEverySceneCorner) {
    const Aabb wsScene{{-60, -2, -80}, {50, 35, 40}};
    for (const CameraParams& cam : cameras()) {
        const std::vector<float> splits = splitsFor(cam, 3);
        for (const glm::vec3& dir : lightDirs()) {
            FitParams p;
            p.zExtension = ZExtension::SceneBounds;
            p.wsSceneBounds = wsScene;
            const CascadeFit fit = fitCascade(cam, splits, 0, dir, p);
            for (int k = 0; k < 8; ++k) {
                const glm::vec3 ws((k & 1) ? wsScene.max.x : wsScene.min.x,
                                   (k & 2) ? wsScene.max.y : wsScene.min.y,
                                   (k & 4) ? wsScene.max.z : wsScene.min.z);
                const float lsZ = (fit.lsView * glm::vec4(ws, 1.0f)).z;
                EXPECT_GE(lsZ, fit.lsBox.min.z - 1e-3f);
                EXPECT_LE(lsZ, fit.lsBox.max.z + 1e-3f);
            }
        }
    }
}

TEST(LightFitTest, DistanceExtensionGrowsMaxZByExactlyTheDistance) {
    const CameraParams cam = cameras()[1];
    const std::vector<float> splits = splitsFor(cam, 4);
    for (const glm::vec3& dir : lightDirs()) {
        FitParams p;
        p.zExtension = ZExtension::None;
        const CascadeFit none = fitCascade(cam, splits, 2, dir, p);
        p.zExtension = ZExtension::Distance;
        p.zExtensionDistance = 75.0f;
        const CascadeFit extended = fitCascade(cam, splits, 2, dir, p);
        EXPECT_FLOAT_EQ(extended.lsBox.max.z, none.lsBox.max.z + 75.0f);
        EXPECT_EQ(extended.lsBox.min, none.lsBox.min);
        EXPECT_EQ(extended.lsBox.max.x, none.lsBox.max.x);
        EXPECT_EQ(extended.lsBox.max.y, none.lsBox.max.y);
    }
}

void expectOrthonormalRotation(const glm::mat4& m, glm::vec3 dir) {
    ASSERT_TRUE(finite(m));
    const glm::mat3 r(m);
    const glm::mat3 rtr = glm::transpose(r) * r;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(rtr[c][k], c == k ? 1.0f : 0.0f, 1e-5f);
    EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f);
    EXPECT_EQ(glm::vec3(m[3]), glm::vec3(0.0f)) << "rotation only, no translation";
    const glm::vec3 lsDir = r * glm::normalize(dir);  // the light travels along ls -Z
    EXPECT_NEAR(lsDir.z, -1.0f, 1e-5f);
}

TEST(LightFitTest, SunStraightUpOrDownGivesFiniteOrthonormalMatrices) {
    const glm::vec3 vertical[] = {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), lightDirection(0, 90),
                                  lightDirection(123, -90), lightDirection(10, 89.5f)};
    for (const glm::vec3& dir : vertical) {
        expectOrthonormalRotation(lightViewMatrix(dir), dir);
        for (FitMode mode : {FitMode::Cascade, FitMode::Sphere}) {
            FitParams p;
            p.fit = mode;
            p.stabilize = true;
            const CascadeFit fit = fitCascade(CameraParams{}, splitsFor(CameraParams{}, 4), 1, dir, p);
            EXPECT_TRUE(finite(fit.lsView) && finite(fit.lsProj) && finite(fit.viewProj));
            EXPECT_GT(fit.texelWorldSize, 0.0f);
        }
    }
    for (const glm::vec3& dir : lightDirs()) expectOrthonormalRotation(lightViewMatrix(dir), dir);
}

TEST(LightFitTest, LightDirectionPointsAwayFromTheSun) {
    const glm::vec3 cases[][2] = {{{0, 0, 0}, {-1, 0, 0}},
                                  {{90, 0, 0}, {0, 0, -1}},
                                  {{45, 90, 0}, {0, -1, 0}},
                                  {{180, 30, 0}, {0.8660254f, -0.5f, 0}}};
    for (const auto& [angles, expected] : cases) {
        const glm::vec3 d = lightDirection(angles.x, angles.y);
        EXPECT_NEAR(glm::length(d - expected), 0.0f, 1e-6f) << angles.x << " " << angles.y;
    }
}

TEST(LightFitTest, SceneFitStartsAtTheFirstSplit) {
    const CameraParams cam;
    const std::vector<float> splits = splitsFor(cam, 4);
    FitParams p;
    p.fit = FitMode::Scene;
    const CascadeFit scene = fitCascade(cam, splits, 2, lightDirection(35, 40), p);
    EXPECT_EQ(scene.vsNear, splits[0]);
    EXPECT_EQ(scene.vsFar, splits[3]);
    p.fit = FitMode::Cascade;
    const CascadeFit own = fitCascade(cam, splits, 2, lightDirection(35, 40), p);
    EXPECT_EQ(own.vsNear, splits[2]);
    EXPECT_EQ(own.vsFar, splits[3]);
    EXPECT_GT(scene.lsBox.extent().x * scene.lsBox.extent().y,
              own.lsBox.extent().x * own.lsBox.extent().y);
}

std::string fitError(int index, int mapSize, glm::vec3 dir) {
    FitParams p;
    p.mapSize = mapSize;
    const std::vector<float> splits = {0.1f, 10.0f, 50.0f};
    try {
        fitCascade(CameraParams{}, splits, index, dir, p);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no exception)";
}

TEST(LightFitTest, RejectsBadIndexMapSizeAndDirection) {
    const glm::vec3 down(0, -1, 0);
    EXPECT_NE(fitError(2, 1024, down).find("index"), std::string::npos) << fitError(2, 1024, down);
    EXPECT_NE(fitError(-1, 1024, down).find("index"), std::string::npos);
    EXPECT_NE(fitError(0, 0, down).find("mapSize"), std::string::npos);
    EXPECT_NE(fitError(0, 1024, glm::vec3(0)).find("wsLightDir"), std::string::npos);
    EXPECT_THROW(lightViewMatrix(glm::vec3(0)), std::invalid_argument);
}

}  // namespace
}  // namespace st::csm

namespace st::csm {
namespace {

// three.js r187 CSM.js: the box is a square as wide as the slice's longer diagonal (far face or
// body), whatever the view's orientation; stabilized, its centre is floored to whole texels of
// width / mapSize; lightDepth puts the far plane that far behind the near one.
TEST(LightFitTest, DiagonalFitIsTheLongerDiagonalSquareWithItsCentreFlooredToTexels) {
    for (const CameraParams& cam : cameras())
        for (const glm::vec3& dir : lightDirs()) {
            FitParams p;
            p.fit = FitMode::Diagonal;
            p.stabilize = true;
            p.snap = Snap::CentreFloor;
            p.mapSize = 2048;
            p.zExtension = ZExtension::Distance;
            p.zExtensionDistance = 199.0f;
            p.lightDepth = 1999.0f;
            const std::vector<float> s = splitsFor(cam, 3);
            for (int i = 0; i < 3; ++i) {
                const CascadeFit fit = fitCascade(cam, s, i, dir, p);
                const Corners c = sliceCornersFromCamera(cam, s[std::size_t(i)], s[std::size_t(i) + 1]);
                const float far = glm::distance(c[6], c[4]), body = glm::distance(c[6], c[0]);
                const float width = std::max(far, body);
                const glm::vec3 e = fit.lsBox.extent();
                EXPECT_NEAR(e.x, width, 1e-4f * width);
                EXPECT_NEAR(e.y, width, 1e-4f * width);
                EXPECT_NEAR(e.z, 1999.0f, 1e-3f);
                const double texel = double(width) / 2048.0;
                const double cx = 0.5 * (double(fit.lsBox.min.x) + double(fit.lsBox.max.x));
                EXPECT_NEAR(cx / texel, std::round(cx / texel), 2e-2) << "centre on the texel grid";
                // The slice's own box (unsnapped) starts at most a texel left of the snapped centre.
                const Aabb slice = fitCascade(cam, s, i, dir, FitParams{.fit = FitMode::Cascade, .zExtension = ZExtension::None, .mapSize = 2048}).lsBox;
                const double sliceCentre = 0.5 * (double(slice.min.x) + double(slice.max.x));
                EXPECT_GE(sliceCentre - cx, -1e-3 * texel);
                EXPECT_LT(sliceCentre - cx, texel * 1.001);
                EXPECT_NEAR(fit.lsBox.max.z, slice.max.z + 199.0f, 1e-2f);
                expectCornersInside(fit, cam, "diagonal");
            }
        }
}

}  // namespace
}  // namespace st::csm

namespace st::csm {
namespace {
// cascades.sphereCentre corners-mean (Babylon's stabilizeCascades): the box is the sphere around the
// slice corners' mean through the farthest corner, radius rounded up to 1/16 m, worked here from the
// corners themselves; it holds every corner, and it is no smaller than the smallest sphere's box.
TEST(LightFitTest, TheCornersMeanSphereIsCentredOnTheCornersAndReachesTheFarthest) {
    for (const CameraParams& cam : cameras()) {
        const std::vector<float> splits = splitsFor(cam, 4);
        for (const glm::vec3& dir : lightDirs())
            for (int i = 0; i < 4; ++i) {
                FitParams p;
                p.fit = FitMode::Sphere;
                p.zExtension = ZExtension::None;
                const CascadeFit smallest = fitCascade(cam, splits, i, dir, p);
                p.sphereAroundCornersMean = true;
                const CascadeFit fit = fitCascade(cam, splits, i, dir, p);
                const Corners ws = sliceCornersFromCamera(cam, splits[std::size_t(i)], splits[std::size_t(i) + 1]);
                glm::dvec3 mean(0.0);
                for (const glm::vec3& c : ws) mean += glm::dvec3(c) / 8.0;
                double r = 0.0;
                for (const glm::vec3& c : ws) r = std::max(r, glm::distance(glm::dvec3(c), mean));
                const double radius = std::ceil(r * 16.0) / 16.0;
                const glm::vec3 centre(fit.lsView * glm::vec4(glm::vec3(mean), 1.0f));
                const std::string what = "cascade " + std::to_string(i);
                EXPECT_NEAR(fit.lsBox.max.x - fit.lsBox.min.x, 2.0 * radius, 1e-3 * radius) << what;
                EXPECT_NEAR(0.5f * (fit.lsBox.max.x + fit.lsBox.min.x), centre.x, 1e-4f * float(radius)) << what;
                EXPECT_NEAR(0.5f * (fit.lsBox.max.y + fit.lsBox.min.y), centre.y, 1e-4f * float(radius)) << what;
                EXPECT_GE(fit.lsBox.max.x - fit.lsBox.min.x, smallest.lsBox.max.x - smallest.lsBox.min.x) << what;
                expectCornersInside(fit, cam, what);
            }
    }
}
}  // namespace
}  // namespace st::csm
