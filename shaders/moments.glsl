// Moment shadow maps: what a depth texel stores and how a receiver reads a filtered texel back.
// Pure functions of their arguments (no blocks), so tests/render/moments_gl_test.cpp can run them
// on known moments against the CPU references of tests/render/moments_reference.h.
// Depths are shadow texture depths, [0, 1] with 0 nearest the sun (docs/architecture.md).
#ifndef ST_MOMENTS_GLSL
#define ST_MOMENTS_GLSL
#include "codes.h"

// EVSM's warp (Lauritzen & McCool 2008, "Layered variance shadow maps", section 4 "exponential
// warp"): depth moved to [-1, 1] and put through exp(c z) (positive) and -exp(-c z) (negative).
vec2 evsmWarp(float z, vec2 exponents) {
    float x = 2.0 * z - 1.0;
    return vec2(exp(exponents.x * x), -exp(-exponents.y * x));
}

// Peters & Klein 2015, "Moment Shadow Mapping", section 4 (optimised quantisation): the affine
// map of (z, z^2, z^3, z^4) into [0, 1]^4 that keeps 16-bit UNORM storage usable. The matrix and
// offset are the paper's; columns here are the paper's rows, so kMsmQuantise * b applies it.
const mat4 kMsmQuantise = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                               32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                               -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                               39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const vec4 kMsmQuantiseOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);

vec4 msmQuantise(vec4 b) { return kMsmQuantise * b + kMsmQuantiseOffset; }
vec4 msmDequantise(vec4 q) { return inverse(kMsmQuantise) * (q - kMsmQuantiseOffset); }

// What one depth texel stores for a moment filter (before blur and quantisation).
vec4 momentsOf(int kind, float z, vec2 exponents) {
    if (kind == ST_FILTER_VSM) return vec4(z, z * z, 0.0, 0.0);
    if (kind == ST_FILTER_MSM) return vec4(z, z * z, z * z * z, z * z * z * z);
    vec2 w = evsmWarp(z, exponents);
    return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}

// Chebyshev's one-sided inequality (seed 004, "Algorithm Details"; Donnelly & Lauritzen 2006):
// an upper bound on the lit share of a receiver at depth t behind a texel of mean m.x and second
// moment m.y; the variance is kept above minVariance.
float chebyshevUpperBound(vec2 m, float t, float minVariance) {
    if (t <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    return variance / (variance + d * d);
}

// EVSM with 2 (positive warp only) or 4 components: the smaller of the two bounds. minVariance is
// given in depth units and scaled by the warp's slope at the receiver, d(warp)/dz = 2 c warp.
float evsmLit(vec4 m, float z, vec2 exponents, bool four, float minVariance) {
    vec2 w = evsmWarp(z, exponents);
    vec2 slope = 2.0 * exponents * abs(w);
    float lit = chebyshevUpperBound(m.xy, w.x, minVariance * slope.x * slope.x);
    if (four) lit = min(lit, chebyshevUpperBound(m.zw, w.y, minVariance * slope.y * slope.y));
    return lit;
}

// Peters & Klein 2015, Algorithm 2 (Hamburger 4MSM): the shadow intensity (0 lit .. 1 shadowed)
// of a receiver at depth zf from moments b = (E z, E z^2, E z^3, E z^4), already biased toward
// (0.5, ...) by the caller. B c = (1, zf, zf^2) with B the 3x3 Hankel matrix of (1, b), by its
// Cholesky factors B = L D L^T; the roots z2 <= z3 of c1 + c2 z + c3 z^2 are the other two
// support points of the distribution with an atom at zf; the result sums the weights in front.
float msmShadowIntensity(vec4 b, float zf) {
    float d22 = b.y - b.x * b.x;
    float l32 = (b.z - b.x * b.y) / d22;
    float d33 = (b.w - b.y * b.y) - l32 * l32 * d22;
    // L y = (1, zf, zf^2), D w = y, L^T c = w.
    float y2 = zf - b.x;
    float y3 = zf * zf - b.y - l32 * y2;
    float c3 = y3 / d33;
    float c2 = y2 / d22 - l32 * c3;
    float c1 = 1.0 - b.x * c2 - b.y * c3;
    float p = c2 / c3;
    float q = c1 / c3;
    float r = sqrt(max(0.25 * p * p - q, 0.0));
    float z2 = -0.5 * p - r;
    float z3 = -0.5 * p + r;
    float g;
    if (zf <= z2) g = 0.0;
    else if (zf <= z3) g = (zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2));
    else g = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3));
    return clamp(g, 0.0, 1.0);
}

#endif
