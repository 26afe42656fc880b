#pragma once
// Ground truth (docs/architecture.md#ground-truth): for each visible pixel, an exact ray
// cast from the surface point toward the sun against the scene's triangles says lit (1) or
// shadowed (0). No shadow map is involved. The BVH (Embree 3) holds exactly the Scene's
// world-space triangles, the ones the GL passes draw; alpha-masked materials let rays through
// where the GL alpha test discards (an occlusion filter samples the base-colour alpha at the hit).
#include "metrics/parallel_rows.h"
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
