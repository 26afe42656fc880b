#pragma once
// UE's cascade distribution (FDirectionalLightSceneProxy::ComputeAccumulatedScale in
// DirectionalLightComponent.cpp) and the exponent that best reproduces a preset's splits.
#include <vector>

namespace st::xport {

// Fraction of (distance - near) at which split `index` of `count` cascades lies:
// sum_{j<index} E^j / sum_{j<count} E^j (0 for index 0, 1 for index count).
double accumulatedScale(double exponent, int index, int count);

struct ExponentFit {
    double exponent = 3.0;  // UE's default when there is nothing to fit
    double maxError = 0.0;  // worst |fraction - model| over the interior splits
};

// Least squares over E in [0.05, 20] (a scan, then a golden-section refinement).
ExponentFit fitDistributionExponent(const std::vector<double>& interiorFractions, int count);

}  // namespace st::xport
