#include "metrics/sun_disc.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>

namespace st::metrics {
namespace {

std::uint32_t reverseBits(std::uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
    v = ((v >> 8) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8);
    return (v >> 16) | (v << 16);
}

// Sobol's second dimension: its generator matrix is Pascal's triangle mod 2, column j being
// v_j = v_{j-1} ^ (v_{j-1} >> 1) from v_0 = 2^31 (Kollig & Keller 2002, "Efficient
// multidimensional sampling", §3.1).
std::uint32_t sobol2(std::uint32_t k) {
    std::uint32_t r = 0;
    for (std::uint32_t v = 1u << 31; k; k >>= 1, v ^= v >> 1)
        if (k & 1u) r ^= v;
    return r;
}

// A 64-bit mix (splitmix64's finaliser) so nearby pixels get unrelated shifts.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

float unit(std::uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }  // 24 bits: exact in float

}  // namespace

DiscScramble discScramble(std::uint32_t seed, std::size_t pixel) {
    const std::uint64_t h = mix((std::uint64_t(seed) << 32) ^ std::uint64_t(pixel) ^ 0x9e3779b97f4a7c15ull);
    return {std::uint32_t(h), std::uint32_t(h >> 32)};
}

glm::vec2 squareSample(std::uint32_t k, DiscScramble s) {
    return {unit(reverseBits(k) ^ s.x), unit(sobol2(k) ^ s.y)};
}

glm::vec2 concentricDisc(glm::vec2 p) {
    const float a = 2.0f * p.x - 1.0f, b = 2.0f * p.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
    constexpr float quarterPi = std::numbers::pi_v<float> / 4.0f;
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = quarterPi * (b / a);
    } else {
        r = b;
        phi = 2.0f * quarterPi - quarterPi * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

glm::vec3 DiscFrame::direction(glm::vec2 p) const { return glm::normalize(toSun + radius * (p.x * u + p.y * v)); }

DiscFrame discFrame(glm::vec3 wsToSun, float angularDiameterDegrees) {
    DiscFrame f;
    f.toSun = glm::normalize(wsToSun);
    const glm::vec3 helper = std::abs(f.toSun.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    f.u = glm::normalize(glm::cross(helper, f.toSun));
    f.v = glm::cross(f.toSun, f.u);
    f.radius = std::tan(glm::radians(0.5f * angularDiameterDegrees));
    return f;
}

}  // namespace st::metrics
