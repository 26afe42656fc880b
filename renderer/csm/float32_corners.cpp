#include "renderer/csm/float32_corners.h"

#include <array>
#include <cmath>

namespace st::csm {
namespace {

// Column-major, clip = M * [x y z 1], as Babylon's Matrix.m; every store rounds to float32.
using Matrix = std::array<double, 16>;

Matrix stored(Matrix m) {
    for (double& x : m) x = static_cast<double>(static_cast<float>(x));
    return m;
}

glm::dvec3 cross(const glm::dvec3& a, const glm::dvec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
glm::dvec3 normalized(const glm::dvec3& a) { return a * (1.0 / std::sqrt(dot(a, a))); }

// The camera as shadowtune builds it (frustum.cpp viewMatrix / projectionMatrix: glm::lookAtRH, a
// vertical-fov perspective), which Babylon's own matrices equal to 6e-7 (engines/babylon/NOTES.md).
Matrix viewOf(const Float32Camera& c) {
    const glm::dvec3 f = normalized(c.target - c.position);
    const glm::dvec3 up = std::abs(f.y) > 0.9998477 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dvec3 s = normalized(cross(f, up));
    const glm::dvec3 u = cross(s, f);
    const glm::dvec3& p = c.position;
    return stored({s.x, u.x, -f.x, 0, s.y, u.y, -f.y, 0, s.z, u.z, -f.z, 0, -dot(s, p), -dot(u, p), dot(f, p), 1});
}

Matrix projectionOf(const Float32Camera& c) {
    const double t = 1.0 / std::tan(c.fovYDegrees * M_PI / 360.0);
    const double n = c.nearPlane, fa = c.farPlane;
    return stored({t / c.aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, -(fa + n) / (fa - n), -1, 0, 0, (-2.0 * fa * n) / (fa - n), 0});
}

// a * b (b applied first), double arithmetic, float32 store (Matrix.multiplyToRef).
Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix o{};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) o[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
    return stored(o);
}

// The general inverse by cofactors, double arithmetic, float32 store (Matrix.invertToRef).
Matrix inverse(const Matrix& m) {
    const auto a = [&](int r, int c) { return m[c * 4 + r]; };
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
    Matrix o{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) o[r * 4 + c] = cof[r][c] / det;  // inverse(c, r) = cof(r, c) / det
    return stored(o);
}

// Vector3.TransformCoordinates: with the w divide.
glm::dvec3 unproject(const Matrix& m, const glm::dvec3& p) {
    const double x = p.x * m[0] + p.y * m[4] + p.z * m[8] + m[12];
    const double y = p.x * m[1] + p.y * m[5] + p.z * m[9] + m[13];
    const double z = p.x * m[2] + p.y * m[6] + p.z * m[10] + m[14];
    const double w = p.x * m[3] + p.y * m[7] + p.z * m[11] + m[15];
    return {x / w, y / w, z / w};
}

}  // namespace

Corners sliceCornersThroughFloat32Inverse(const Float32Camera& cam, double b0, double b1) {
    const Matrix inv = inverse(multiply(projectionOf(cam), viewOf(cam)));
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
