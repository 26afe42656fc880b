#include "renderer/csm/float32_corners.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <array>
#include <cmath>

namespace st::csm {
namespace {

// Every store of an engine's Matrix rounds to float32 (Babylon's Matrix.m is a Float32Array); the
// arithmetic between stores is double. glm's column-major dmat4 is Babylon's layout, and its
// products sum in Babylon's order (Matrix.multiplyToRef).
glm::dmat4 stored(glm::dmat4 m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = static_cast<double>(static_cast<float>(m[c][r]));
    return m;
}

// The camera as shadowtune builds it (frustum.cpp viewMatrix / projectionMatrix: glm::lookAtRH, a
// vertical-fov perspective), which Babylon's own matrices equal to 6e-7 (engines/babylon/NOTES.md).
glm::dmat4 viewOf(const Float32Camera& c) {
    const glm::dvec3 f = glm::normalize(c.target - c.position);
    const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(stableUp(glm::vec3(f)))));
    const glm::dvec3 u = glm::cross(s, f);
    const glm::dvec3& p = c.position;
    return stored(glm::dmat4(s.x, u.x, -f.x, 0, s.y, u.y, -f.y, 0, s.z, u.z, -f.z, 0,  //
                             -glm::dot(s, p), -glm::dot(u, p), glm::dot(f, p), 1));
}

glm::dmat4 projectionOf(const Float32Camera& c) {
    const double t = 1.0 / std::tan(c.fovYDegrees * M_PI / 360.0);
    const double n = c.nearPlane, fa = c.farPlane;
    return stored(glm::dmat4(t / c.aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, -(fa + n) / (fa - n), -1, 0, 0,
                             (-2.0 * fa * n) / (fa - n), 0));
}

// The general inverse by cofactors, as engines/babylon/test/reference.mjs (Matrix.invertToRef):
// double arithmetic, float32 store. glm::inverse orders its sums otherwise; the float32 store
// hides most of that, not all, and these matrices magnify every bit (far / near = 5000).
glm::dmat4 inverse(const glm::dmat4& m) {
    const auto a = [&](int r, int c) { return m[c][r]; };
    const auto det3 = [&](int r0, int r1, int r2, int c0, int c1, int c2) {
        return a(r0, c0) * (a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1)) -
               a(r0, c1) * (a(r1, c0) * a(r2, c2) - a(r1, c2) * a(r2, c0)) +
               a(r0, c2) * (a(r1, c0) * a(r2, c1) - a(r1, c1) * a(r2, c0));
    };
    const auto others = [](int skip) {
        std::array<int, 3> o{};
        for (int i = 0, k = 0; i < 4; ++i)
            if (i != skip) o[std::size_t(k++)] = i;
        return o;
    };
    double cof[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const auto rs = others(r), cs = others(c);
            cof[r][c] = ((r + c) % 2 ? -1.0 : 1.0) * det3(rs[0], rs[1], rs[2], cs[0], cs[1], cs[2]);
        }
    double det = 0.0;
    for (int c = 0; c < 4; ++c) det += a(0, c) * cof[0][c];
    glm::dmat4 o;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) o[r][c] = cof[r][c] / det;  // inverse(row c, column r) = cof(r, c) / det
    return stored(o);
}

}  // namespace

Corners sliceCornersThroughFloat32Inverse(const Float32Camera& cam, double b0, double b1) {
    const glm::dmat4 inv = inverse(stored(projectionOf(cam) * viewOf(cam)));
    const double ndcX[4] = {-1, 1, 1, -1};
    const double ndcY[4] = {-1, -1, 1, 1};
    Corners ws;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 nearEnd = unproject(inv, {ndcX[i], ndcY[i], -1.0});
        const glm::dvec3 edge = unproject(inv, {ndcX[i], ndcY[i], 1.0}) - nearEnd;
        ws[i] = glm::vec3(nearEnd + edge * b0);
        ws[i + 4] = glm::vec3(nearEnd + edge * b1);
    }
    return ws;
}

}  // namespace st::csm
