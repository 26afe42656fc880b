#pragma once
// Ground truth (docs/architecture.md#ground-truth): for each visible pixel, an exact ray
// cast from the surface point toward the sun against the scene's triangles says lit (1) or
// shadowed (0). No shadow map is involved. The BVH (Embree 3) holds exactly the Scene's
// world-space triangles, the ones the GL passes draw; alpha-masked materials let rays through
// where the GL alpha test discards (an occlusion filter samples the base-colour alpha at the hit).
#include "metrics/parallel_rows.h"
#include "metrics/sun_disc.h"
#include "renderer/render/measure_samples.h"
#include "renderer/scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace st::metrics {

// Where a shadow ray starts: the surface point moved along its triangle's normal by
// metres + perMetre * max(|p|, |p - eye|). The read-back position is a float the rasteriser
// interpolated, so it can sit a hair under its own triangle (about 1e-7 of the coordinates'
// magnitude, a few 1e-5 m at 300 m); the offset clears that with a margin of ten. It is kept
// that small because it moves every true shadow edge by offset / tan(sun elevation): at 15 m
// from the eye 2.5e-4 m, under 1 % of a shadow texel of the shipped presets.
struct RayOffset {
    float metres = 1e-4f;
    float perMetre = 1e-5f;
};

// The sun as a disc (docs/architecture.md#the-suns-disc): its angular diameter, the rays per
// pixel over it, and the seed of their pattern (sun_disc.h).
struct SunDisc {
    float angularDiameter = 0.53f;  // degrees; 0 = a point sun
    int rays = 16;
    std::uint32_t seed = kSunDiscSeed;
    bool exhaustive = false;  // every ray at every receiver (to check the adaptive trace against)
    bool operator==(const SunDisc&) const = default;
};

// Rays every receiver gets over the disc before the rest are traced only where the pixel's
// 3x3 block disagrees (GroundTruth::traceDisc).
inline constexpr int kDiscFirstRays = 8;

// The soft truth of a frame, per pixel (0 where there is no receiver).
struct SoftTruth {
    std::vector<float> visible;  // fraction of the disc's rays that reach the sun, 0..1
    std::vector<float> blocker;  // metres along the centre ray to the first hit; +inf where it reaches the sun
};

class GroundTruth {
public:
    // Builds the BVH over `scene` (which must outlive this). Throws std::runtime_error if Embree
    // cannot start.
    explicit GroundTruth(const Scene& scene);
    ~GroundTruth();
    GroundTruth(const GroundTruth&) = delete;
    GroundTruth& operator=(const GroundTruth&) = delete;

    // Per pixel of `samples`: 1 lit, 0 shadowed. Pixels with no surface are 0. Pixels facing
    // away from the sun (by the shading normal, or by the triangle's own normal: the terminator
    // band of smooth meshes) are 0 without a ray: the sun is behind their own surface, and the
    // accuracy metrics leave them out. Every receiver gets one ray, from its triangle's plane;
    // rows are spread over the cores `control` allows. Rows a cancel skipped are left 0: a
    // cancelled trace is for throwing away.
    std::vector<std::uint8_t> trace(const MeasureSamples& samples, glm::vec3 wsToSun, glm::vec3 wsEye,
                                    RayOffset offset = {}, const RowControl& control = {}) const;

    // Per receiver of `samples`: the visible fraction of `disc` around wsToSun (disc.rays rays
    // from the same origin as trace(), traced as 8-ray packets) and the distance to the first
    // hit along the centre ray. Every receiver gets the centre ray and kDiscFirstRays rays; the
    // rest only where its 3x3 block of receivers is not unanimously lit or in umbra (an
    // occluder hidden from all of the block's rays covers under an eighth of the disc: the
    // error it leaves is below that fraction). With a point sun (angular diameter or rays 0)
    // the fraction is the centre ray's 0 or 1, the hard truth. Rows as trace(), twice.
    SoftTruth traceDisc(const MeasureSamples& samples, glm::vec3 wsToSun, const SunDisc& disc, glm::vec3 wsEye,
                        RayOffset offset = {}, const RowControl& control = {}) const;

    // One ray: true if nothing blocks the way from wsOrigin toward the sun.
    bool reachesSun(glm::vec3 wsOrigin, glm::vec3 wsToSun) const;

    // The truth at one surface point: its ray starts `offset` along wsNormal, the triangle's
    // normal (see RayOffset). Does not check that the surface faces the sun.
    bool lit(glm::vec3 wsPoint, glm::vec3 wsNormal, glm::vec3 wsToSun, glm::vec3 wsEye, RayOffset offset = {}) const;

    double buildMs() const;  // time to build the BVH

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace st::metrics
