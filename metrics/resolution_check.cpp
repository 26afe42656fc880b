#include "metrics/resolution_check.h"

#include "renderer/csm/conventions.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace st::metrics {

ResolutionCheck::ResolutionCheck(const GroundTruth& truth, const csm::CascadePlan& plan, int mapSize, glm::vec3 wsEye,
                                 RayOffset offset)
    : truth_(&truth), wsToSun_(-plan.wsLightDir), wsEye_(wsEye), offset_(offset) {
    for (const csm::CascadeFit& fit : plan.cascades) {
        sizes_.push_back(double(fit.mapSize > 0 ? fit.mapSize : mapSize));
        const glm::dmat4 m = glm::dmat4(csm::clipToTexture() * fit.viewProj);
        toTexture_.push_back(m);
        fromTexture_.push_back(glm::inverse(m));
    }
}

// Offsets from a texel centre, in texels: the centre, then a hair either side on each axis. The
// rasteriser decides coverage at the centre with snapped (llvmpipe: 1/256 texel) vertex
// positions, so a silhouette passing within that of the centre may fall either way.
constexpr double kJitter = 1.0 / 64.0;
constexpr double kOffsets[5][2] = {{0, 0}, {-kJitter, 0}, {kJitter, 0}, {0, -kJitter}, {0, kJitter}};

bool ResolutionCheck::truthUnderTexel(glm::dvec2 tsCentre, double tsZ, glm::dvec3 p, glm::dvec3 n, int cascade,
                                      bool lit) const {
    const glm::dvec3 light = -glm::dvec3(wsToSun_);
    const double size = sizes_[std::size_t(cascade)];
    for (const auto& d : kOffsets) {
        const glm::dvec4 ts(tsCentre + glm::dvec2(d[0], d[1]) / size, tsZ, 1.0);
        const glm::dvec3 x(fromTexture_[std::size_t(cascade)] * ts);
        // Along the light ray through the centre to the receiver's plane: n . (x + t L - p) = 0.
        const glm::dvec3 q = x + light * (glm::dot(n, p - x) / glm::dot(n, light));
        if (truth_->lit(glm::vec3(q), glm::vec3(n), wsToSun_, wsEye_, offset_) == lit) return true;
    }
    return false;
}

bool ResolutionCheck::explains(glm::vec3 wsPoint, glm::vec3 wsNormal, int cascade, bool mapLit) const {
    if (cascade < 0 || cascade >= int(toTexture_.size())) return false;
    const glm::dvec3 p(wsPoint), n(wsNormal);
    if (glm::dot(n, glm::dvec3(wsToSun_)) <= 0.0) return false;  // not a receiver: no plane to land on
    const glm::dvec4 ts = toTexture_[std::size_t(cascade)] * glm::dvec4(p, 1.0);
    const double size = sizes_[std::size_t(cascade)];
    // The lower-left of the 2x2 texel centres around ts: centres sit at (i + 0.5) / size.
    const double i0 = std::floor(ts.x * size - 0.5), j0 = std::floor(ts.y * size - 0.5);
    for (int dj = 0; dj < 2; ++dj) {
        for (int di = 0; di < 2; ++di) {
            const glm::dvec2 centre((i0 + di + 0.5) / size, (j0 + dj + 0.5) / size);
            if (truthUnderTexel(centre, ts.z, p, n, cascade, mapLit)) return true;
        }
    }
    return false;
}

}  // namespace st::metrics
