#pragma once
// How a real engine's shadow factor compares with shadowtune's model of the same settings and with
// the ground truth (`engine-check`, docs/engines.md). Both factors are judged the same way: lit
// where the filtered factor is >= 0.5, the filtered error |f - t| against the sun's-disc truth t.
// Scored pixels: shadowtune's receivers (accuracy.h) that the engine drew too.
#include "renderer/render/measure_samples.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st::metrics {

// What one renderer's factor scores against the truth.
struct FactorScore {
    std::size_t falseShadow = 0;  // factor says shadow, truth lit
    std::size_t falseLight = 0;   // factor says lit, truth shadow
    double filteredAbsErrorSum = 0.0;
};

// Two factors this close count as the same shade in factorAgreement (a 0.1 step of a 0..1 factor).
inline constexpr float kBorderlineFactor = 0.1f;

struct EngineAgreement {
    std::size_t scored = 0;        // receivers in both images
    std::size_t agree = 0;         // same lit/shadowed state in both
    std::size_t engineOnlyShadow = 0, modelOnlyShadow = 0;
    std::size_t engineMissing = 0; // shadowtune receivers the engine did not draw (coverage 0)
    // The factors themselves: a lit/shadowed state is the factor against 0.5, so two factors a hair
    // apart on either side of 0.5 (acne's bands under a filter) disagree in state. `borderline`
    // counts the disagreeing pixels whose factors differ by at most kBorderlineFactor.
    double factorAbsDiffSum = 0.0;
    std::size_t borderline = 0;
    FactorScore engine, model;
    double agreement() const { return scored ? double(agree) / double(scored) : 0.0; }
    double misclassified(const FactorScore& f) const {
        return scored ? double(f.falseShadow + f.falseLight) / double(scored) : 0.0;
    }
    double filteredError(const FactorScore& f) const { return scored ? f.filteredAbsErrorSum / double(scored) : 0.0; }
    double meanFactorDifference() const { return scored ? factorAbsDiffSum / double(scored) : 0.0; }
    // Same state, or factors within kBorderlineFactor of each other.
    double factorAgreement() const { return scored ? double(agree + borderline) / double(scored) : 0.0; }
};

// Per pixel of the disagreement map.
enum class AgreementClass : std::uint8_t { NotScored, AgreeLit, AgreeShadow, EngineOnlyShadow, ModelOnlyShadow };

// engine: per pixel (factor, cascade, N.L, coverage), rows top first (engines/README.md);
// model: shadowtune's samples of the same view (shadow.y is its filtered factor); truth: 1 lit,
// 0 shadowed per pixel; soft: the visible share of the sun's disc per pixel. Sizes must match
// (std::invalid_argument otherwise). `classes`, if given, receives the disagreement map.
EngineAgreement compareWithEngine(const std::vector<glm::vec4>& engine, const MeasureSamples& model,
                                  const std::vector<std::uint8_t>& truth, const std::vector<float>& soft,
                                  std::vector<AgreementClass>* classes = nullptr);

}  // namespace st::metrics
