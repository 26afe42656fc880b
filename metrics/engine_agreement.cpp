#include "metrics/engine_agreement.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace st::metrics {
namespace {

void scoreFactor(FactorScore& s, float factor, bool truthLit, float soft) {
    const bool lit = factor >= 0.5f;
    s.falseShadow += !lit && truthLit;
    s.falseLight += lit && !truthLit;
    s.filteredAbsErrorSum += std::abs(double(factor) - double(soft));
}

}  // namespace

EngineAgreement compareWithEngine(const std::vector<glm::vec4>& engine, const MeasureSamples& model,
                                  const std::vector<std::uint8_t>& truth, const std::vector<float>& soft,
                                  std::vector<AgreementClass>* classes) {
    const std::size_t n = model.size();
    if (engine.size() != n || truth.size() != n || soft.size() != n)
        throw std::invalid_argument("engine samples (" + std::to_string(engine.size()) + "), truth (" +
                                    std::to_string(truth.size()) + ") and soft truth (" + std::to_string(soft.size()) +
                                    ") must each hold the model's " + std::to_string(n) + " pixels");
    EngineAgreement a;
    if (classes) classes->assign(n, AgreementClass::NotScored);
    for (std::size_t i = 0; i < n; ++i) {
        if (!model.receiver(i)) continue;
        if (engine[i].w <= 0.5f) {
            ++a.engineMissing;
            continue;
        }
        ++a.scored;
        const float fe = engine[i].x, fm = model.shadow[i].y;
        const bool litE = fe >= 0.5f, litM = fm >= 0.5f;
        scoreFactor(a.engine, fe, truth[i] != 0, soft[i]);
        scoreFactor(a.model, fm, truth[i] != 0, soft[i]);
        const float diff = std::abs(fe - fm);
        a.factorAbsDiffSum += diff;
        if (litE != litM && diff <= kBorderlineFactor) ++a.borderline;
        AgreementClass c;
        if (litE == litM) {
            ++a.agree;
            c = litE ? AgreementClass::AgreeLit : AgreementClass::AgreeShadow;
        } else if (!litE) {
            ++a.engineOnlyShadow;
            c = AgreementClass::EngineOnlyShadow;
        } else {
            ++a.modelOnlyShadow;
            c = AgreementClass::ModelOnlyShadow;
        }
        if (classes) (*classes)[i] = c;
    }
    return a;
}

}  // namespace st::metrics
