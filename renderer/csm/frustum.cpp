#include "renderer/csm/frustum.h"

#include "renderer/csm/error_text.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace st::csm {
namespace {

void checkRange(float vsNear, float vsFar, const char* nearName, const char* farName) {
    if (!std::isfinite(vsNear) || vsNear < 0.0f)
        throw std::invalid_argument(std::string(nearName) + " must be >= 0, got " + str(vsNear));
    if (!std::isfinite(vsFar) || vsNear >= vsFar)
        throw std::invalid_argument(std::string(nearName) + " (" + str(vsNear) +
                                    ") must be less than " + farName + " (" + str(vsFar) + ")");
}

// Camera basis as glm::lookAtRH builds it: s right, u up, f forward (vs -Z).
struct Basis {
    glm::vec3 s, u, f;
};

Basis cameraBasis(const CameraParams& c) {
    const glm::vec3 f = glm::normalize(c.wsTarget - c.wsPosition);
    const glm::vec3 s = glm::normalize(glm::cross(f, stableUp(f)));
    return {s, glm::cross(s, f), f};
}

// The four corners of the slice's cross-section at view depth d, in vs (seed 002: x = d tan(fovX/2),
// y = d tan(fovY/2)), in the Corners order (-x,-y), (+x,-y), (+x,+y), (-x,+y).
void vsCornersAt(const CameraParams& c, float d, glm::vec3* out) {
    const float ty = std::tan(0.5f * c.fovY);
    const float x = d * ty * c.aspect;
    const float y = d * ty;
    out[0] = {-x, -y, -d};
    out[1] = {x, -y, -d};
    out[2] = {x, y, -d};
    out[3] = {-x, y, -d};
}

}  // namespace

glm::dvec3 unproject(const glm::dmat4& invViewProj, glm::dvec3 ndc) {
    const glm::dvec4 h = invViewProj * glm::dvec4(ndc, 1.0);
    return glm::dvec3(h) / h.w;
}

void validateCamera(const CameraParams& c) {
    if (!std::isfinite(c.nearPlane) || c.nearPlane <= 0.0f)
        throw std::invalid_argument("camera.nearPlane must be > 0, got " + str(c.nearPlane));
    checkRange(c.nearPlane, c.farPlane, "camera.nearPlane", "camera.farPlane");
    if (!(c.fovY > 0.0f && c.fovY < glm::pi<float>()))
        throw std::invalid_argument("camera.fovY must be in (0, pi) radians, got " + str(c.fovY));
    if (!(c.aspect > 0.0f) || !std::isfinite(c.aspect))
        throw std::invalid_argument("camera.aspect must be > 0, got " + str(c.aspect));
    const glm::vec3 d = c.wsTarget - c.wsPosition;
    if (!(glm::dot(d, d) > 0.0f) || !std::isfinite(glm::dot(d, d)))
        throw std::invalid_argument("camera.target must differ from camera.position");
}

glm::vec3 stableUp(glm::vec3 wsForward) {
    const float cosOneDegree = 0.99984770f;  // cos(1 deg)
    const float alongY = std::abs(glm::dot(glm::normalize(wsForward), glm::vec3(0, 1, 0)));
    return alongY > cosOneDegree ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
}

glm::mat4 viewMatrix(const CameraParams& c) {
    validateCamera(c);
    const Basis b = cameraBasis(c);
    glm::mat4 m(1.0f);  // rows s, u, -f: the transpose of the rotation in inverseViewMatrix
    for (int i = 0; i < 3; ++i) {
        m[i][0] = b.s[i];
        m[i][1] = b.u[i];
        m[i][2] = -b.f[i];
    }
    m[3] = glm::vec4(-glm::dot(b.s, c.wsPosition), -glm::dot(b.u, c.wsPosition),
                     glm::dot(b.f, c.wsPosition), 1.0f);
    return m;
}

glm::mat4 inverseViewMatrix(const CameraParams& c) {
    validateCamera(c);
    const Basis b = cameraBasis(c);
    return glm::mat4(glm::vec4(b.s, 0.0f), glm::vec4(b.u, 0.0f), glm::vec4(-b.f, 0.0f),
                     glm::vec4(c.wsPosition, 1.0f));
}

glm::mat4 projectionMatrix(const CameraParams& c) {
    validateCamera(c);
    return glm::perspective(c.fovY, c.aspect, c.nearPlane, c.farPlane);
}

Corners sliceCornersFromCamera(const CameraParams& c, float vsNear, float vsFar) {
    checkRange(vsNear, vsFar, "vsNear", "vsFar");
    const glm::mat4 wsFromVs = inverseViewMatrix(c);
    Corners vs;
    vsCornersAt(c, vsNear, &vs[0]);
    vsCornersAt(c, vsFar, &vs[4]);
    Corners ws;
    for (std::size_t i = 0; i < vs.size(); ++i) ws[i] = glm::vec3(wsFromVs * glm::vec4(vs[i], 1.0f));
    return ws;
}

// Seed 003 "Frustum Splits": unproject the NDC cube's corners (z = -1 near, +1 far), then move
// along each of the four edges to the slice depths (depth is linear along an edge). The far
// corners of a float matrix are poor in depth: their w = 1/f is the difference of two ~1/(2n)
// terms, an error of ~eps f/(2n) (1e-4 for n = 0.1, f = 400) that slides them along their rays.
// So the edge parameter comes from the depth measured along the near plane's normal instead of
// assuming the far corners sit exactly at camFar; camFar is only checked.
Corners sliceCornersFromInverseViewProj(const glm::mat4& invViewProj, float camNear,
                                        float camFar, float vsNear, float vsFar) {
    checkRange(camNear, camFar, "camNear", "camFar");
    checkRange(vsNear, vsFar, "vsNear", "vsFar");
    const glm::dmat4 m(invViewProj);
    const double ndcX[4] = {-1, 1, 1, -1};
    const double ndcY[4] = {-1, -1, 1, 1};
    glm::dvec3 a[4], b[4];  // near and far ends of each edge
    for (std::size_t i = 0; i < 4; ++i) {
        a[i] = unproject(m, {ndcX[i], ndcY[i], -1.0});
        b[i] = unproject(m, {ndcX[i], ndcY[i], 1.0});
    }
    glm::dvec3 forward = glm::normalize(glm::cross(a[1] - a[0], a[3] - a[0]));
    if (glm::dot(forward, b[0] - a[0]) < 0.0) forward = -forward;
    Corners ws;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 edge = b[i] - a[i];
        const double perDepth = 1.0 / glm::dot(edge, forward);  // edge parameter per metre of depth
        ws[i] = glm::vec3(a[i] + edge * ((vsNear - static_cast<double>(camNear)) * perDepth));
        ws[i + 4] = glm::vec3(a[i] + edge * ((vsFar - static_cast<double>(camNear)) * perDepth));
    }
    return ws;
}

}  // namespace st::csm
