#pragma once
// Camera matrices and frustum slices in world space.
#include "renderer/csm/geometry.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace st::csm {

struct CameraParams {
    glm::vec3 wsPosition{0.0f, 0.0f, 5.0f};
    glm::vec3 wsTarget{0.0f};
    float fovY = 1.0471976f;  // radians, vertical
    float aspect = 16.0f / 9.0f;
    float nearPlane = 0.1f;
    float farPlane = 400.0f;
};

// Throws std::invalid_argument naming the bad field (near/far, fovY, aspect, position==target).
void validateCamera(const CameraParams& c);

// Up vector for a look-at along wsForward: world +Y, or +Z when |dot(forward, Y)| > cos(1 deg).
glm::vec3 stableUp(glm::vec3 wsForward);

// World up (+Y), or +Z when the view direction is (nearly) vertical, so lookAt never degenerates.
glm::mat4 viewMatrix(const CameraParams& c);
// vs -> ws, built from the same basis as viewMatrix (exact rigid inverse, no glm::inverse).
glm::mat4 inverseViewMatrix(const CameraParams& c);
glm::mat4 projectionMatrix(const CameraParams& c);  // GL clip space, depth [-1,1]

// Slice [vsNear, vsFar] of the view frustum from the camera parameters (seed 002: tangent of the
// half angles times the depth, then the inverse view matrix).
Corners sliceCornersFromCamera(const CameraParams& c, float vsNear, float vsFar);

// An NDC point through an inverse view-projection, with the w divide.
glm::dvec3 unproject(const glm::dmat4& invViewProj, glm::dvec3 ndc);

// The same slice from the inverse view-projection (seed 003 "Frustum Splits"): unproject the NDC
// cube's corners to the camera frustum, then interpolate along each edge to the slice depths.
// camNear/camFar are the planes the projection was built with.
Corners sliceCornersFromInverseViewProj(const glm::mat4& invViewProj, float camNear,
                                        float camFar, float vsNear, float vsFar);

}  // namespace st::csm
