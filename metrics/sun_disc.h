#pragma once
// Directions over the sun's disc for the soft ground truth (docs/architecture.md#the-suns-disc).
// Sample k of a pixel is point k of a scrambled (0,2)-sequence (van der Corput in x, Sobol's
// second dimension in y), mapped onto the unit disc by Shirley and Chiu's concentric map. Every
// prefix of 2^m samples is a (0,m,2)-net: one point in each of the 2^m equal-area strata of
// every elementary partition of the square, which the concentric map carries onto equal-area
// strata of the disc (Shirley & Chiu 1997, "A low distortion map between disk and square", §3).
// Each pixel XORs a hash of (seed, pixel) into both coordinates (a digital shift, which keeps the
// net property), so neighbouring pixels' patterns do not line up into bands and a run with the
// same seed traces the very same rays.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

namespace st::metrics {

inline constexpr std::uint32_t kSunDiscSeed = 0x5eed5u;

// The digital shift of `pixel` under `seed`: two 32-bit words.
struct DiscScramble {
    std::uint32_t x = 0, y = 0;
};
DiscScramble discScramble(std::uint32_t seed, std::size_t pixel);

// Point k of the scrambled sequence in the unit square, then on the unit disc.
glm::vec2 squareSample(std::uint32_t k, DiscScramble s);
glm::vec2 concentricDisc(glm::vec2 unitSquare);

// The disc of angular diameter `degrees` around wsToSun, as a tangent-plane frame: a direction
// to point p of the unit disc is normalize(toSun + radius * (p.x * u + p.y * v)), with radius the
// tangent of the half angle, so uniform points on the unit disc are uniform over the disc's
// cross-section (the solid angle of a 0.53 degree sun is flat to 1e-5).
struct DiscFrame {
    glm::vec3 toSun{0.0f, 1.0f, 0.0f};
    glm::vec3 u{1.0f, 0.0f, 0.0f}, v{0.0f, 0.0f, 1.0f};
    float radius = 0.0f;
    glm::vec3 direction(glm::vec2 unitDisc) const;
};
DiscFrame discFrame(glm::vec3 wsToSun, float angularDiameterDegrees);

}  // namespace st::metrics
