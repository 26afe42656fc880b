#include "renderer/csm/frustum.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::csm {
namespace {

CameraParams camera(glm::vec3 pos, glm::vec3 target, float fovY, float aspect, float n, float f) {
    CameraParams c;
    c.wsPosition = pos;
    c.wsTarget = target;
    c.fovY = fovY;
    c.aspect = aspect;
    c.nearPlane = n;
    c.farPlane = f;
    return c;
}

// Includes the default camera (f/n = 4000): there the far corners of a float inverse
// view-projection are off in depth by ~1e-4 relative, which sliceCornersFromInverseViewProj
// must not pass on.
std::vector<CameraParams> testCameras() {
    return {
        CameraParams{},
        camera({0, 1.7f, 10}, {0, 1, 0}, 1.0471976f, 16.0f / 9.0f, 0.5f, 400.0f),
        camera({-30, 12, 4}, {5, 0, -20}, 0.7f, 1.0f, 1.0f, 1000.0f),
        camera({3, 50, 3}, {3.2f, 0, 3}, 1.2f, 2.0f, 0.1f, 200.0f),  // nearly straight down
        camera({0, 2, 0}, {0, 40, 0}, 0.9f, 0.75f, 0.25f, 100.0f),   // straight up
        camera({100, -5, 250}, {90, -4, 240}, 1.5f, 1.3f, 0.2f, 60.0f),
    };
}

TEST(FrustumTest, CornerMethodsAgreeIncludingNearTheFarPlane) {
    for (const CameraParams& c : testCameras()) {
        // Float inverse, as a renderer would compute it.
        const glm::mat4 invViewProj = glm::inverse(projectionMatrix(c) * viewMatrix(c));
        const float n = c.nearPlane;
        const float f = c.farPlane;
        const std::vector<std::pair<float, float>> slices = {
            {n, f}, {n, 3 * n}, {0.2f * f, 0.5f * f}, {0.9f * f, f}, {0.999f * f, f}};
        for (const auto& [a, b] : slices) {
            const Corners fromCamera = sliceCornersFromCamera(c, a, b);
            const Corners fromMatrix = sliceCornersFromInverseViewProj(invViewProj, n, f, a, b);
            for (std::size_t i = 0; i < 8; ++i) {
                // Relative to the corner's distance from the eye, at least 1 m: float ws positions
                // carry ~|p| * 6e-8 absolute error whatever the slice's size.
                const float scale = std::max(glm::length(fromCamera[i] - c.wsPosition), 1.0f);
                EXPECT_LE(glm::length(fromCamera[i] - fromMatrix[i]), 1e-4f * scale)
                    << "slice [" << a << ", " << b << "] corner " << i;
            }
        }
    }
}

TEST(FrustumTest, CornerOrderAndDepthInViewSpace) {
    const CameraParams c = testCameras()[1];
    const glm::mat4 view = viewMatrix(c);
    const Corners ws = sliceCornersFromCamera(c, 2.0f, 30.0f);
    const float sx[4] = {-1, 1, 1, -1};
    const float sy[4] = {-1, -1, 1, 1};
    for (std::size_t i = 0; i < 8; ++i) {
        const glm::vec3 vs(view * glm::vec4(ws[i], 1.0f));
        EXPECT_NEAR(-vs.z, i < 4 ? 2.0f : 30.0f, 1e-4f) << i;
        EXPECT_GT(vs.x * sx[i % 4], 0.0f) << i;
        EXPECT_GT(vs.y * sy[i % 4], 0.0f) << i;
        // On the frustum's side planes: |y| = d tan(fovY/2), |x| = aspect |y|.
        EXPECT_NEAR(std::abs(vs.y), -vs.z * std::tan(0.5f * c.fovY), 1e-4f * -vs.z);
        EXPECT_NEAR(std::abs(vs.x), c.aspect * std::abs(vs.y), 1e-4f * -vs.z);
    }
}

TEST(FrustumTest, InverseViewIsTheInverseForVerticalAndOrdinaryCameras) {
    for (const CameraParams& c : testCameras()) {
        const glm::mat4 product = viewMatrix(c) * inverseViewMatrix(c);
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row)
                EXPECT_NEAR(product[col][row], col == row ? 1.0f : 0.0f, 1e-4f);
        const glm::vec3 vsTarget(viewMatrix(c) * glm::vec4(c.wsTarget, 1.0f));
        EXPECT_NEAR(glm::length(glm::vec2(vsTarget)), 0.0f, 1e-4f) << "target on the -Z axis";
        EXPECT_LT(vsTarget.z, 0.0f);
    }
}

std::string cameraError(const CameraParams& c) {
    try {
        viewMatrix(c);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no exception)";
}

TEST(FrustumTest, RejectsDegenerateCameras) {
    CameraParams c;
    c.wsTarget = c.wsPosition;
    EXPECT_THROW(viewMatrix(c), std::invalid_argument);
    EXPECT_NE(cameraError(c).find("target"), std::string::npos) << cameraError(c);
    c = CameraParams{};
    c.fovY = 0.0f;
    EXPECT_NE(cameraError(c).find("fovY"), std::string::npos) << cameraError(c);
    c = CameraParams{};
    c.nearPlane = 5.0f;
    c.farPlane = 1.0f;
    EXPECT_NE(cameraError(c).find("nearPlane (5)"), std::string::npos) << cameraError(c);
    EXPECT_THROW(sliceCornersFromCamera(CameraParams{}, 10.0f, 2.0f), std::invalid_argument);
}

}  // namespace
}  // namespace st::csm
