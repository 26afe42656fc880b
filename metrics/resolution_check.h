#pragma once
// Which errors the map's resolution explains (the edge band of the misclassification split,
// docs/architecture.md#misclassification), decided exactly rather than by a screen-space
// distance. The unfiltered test at a point answers for the shadow-map texel the point falls
// in: the caster depth stored there was rasterised at the texel's centre. So if the truth at
// the receiver point under a nearby texel centre agrees with the map, the error is the map's
// finite resolution at a true shadow edge (expected aliasing, "edge"); if the truth under every
// nearby centre disagrees, the map got the texel itself wrong (acne, a leak, a missing caster,
// a seam: "gross"). Screen-space bands miss the sub-pixel casters that matter most (poles,
// wires, leaves): their true shadow can fall between pixel centres while a texel centre still
// catches it.
#include "metrics/ground_truth.h"
#include "renderer/csm/cascade_plan.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace st::metrics {

class ResolutionCheck {
public:
    // `plan` is the frame whose maps were tested; each cascade's map has its own fit's mapSize
    // texels per side (cascades.mapSizes), `mapSize` for fits that carry none.
    ResolutionCheck(const GroundTruth& truth, const csm::CascadePlan& plan, int mapSize, glm::vec3 wsEye,
                    RayOffset offset = {});

    // True if the truth at one of the receiver points under the 2x2 texel centres nearest to
    // wsPoint's shadow coordinate in `cascade` equals `mapLit`. The receiver points are where
    // the light rays through those centres meet the plane of (wsPoint, wsNormal), wsNormal
    // being the triangle's own normal (the receiver-plane assumption bias methods rely on: over
    // a plane a perfect bias leaves only the resolution's errors). The nearest
    // centre is always among the four, so disagreeing rounding between GPU and CPU cannot turn
    // an aliasing error into a gross one; nor can a silhouette that passes within 1/64 texel of
    // a centre, which the rasteriser's snapping may put either side. The normal offset of the bias is not applied: a shadow
    // it moves by more than a texel is an error of the bias, not of the resolution.
    bool explains(glm::vec3 wsPoint, glm::vec3 wsNormal, int cascade, bool mapLit) const;

private:
    // Whether the truth at the receiver point under the texel centre tsCentre (or a hair beside
    // it) equals `lit`.
    bool truthUnderTexel(glm::dvec2 tsCentre, double tsZ, glm::dvec3 p, glm::dvec3 n, int cascade, bool lit) const;

    const GroundTruth* truth_;
    std::vector<glm::dmat4> toTexture_;    // ws -> shadow texture coordinates, per cascade
    std::vector<glm::dmat4> fromTexture_;  // the inverse
    glm::vec3 wsToSun_;
    glm::vec3 wsEye_;
    std::vector<double> sizes_;  // texels per side, per cascade
    RayOffset offset_;
};

}  // namespace st::metrics
