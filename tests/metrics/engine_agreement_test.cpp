// metrics/engine_agreement.h on samples built so the answer is known: which pixels are scored,
// the agreement, and both factors' misclassified share and filtered error against the truth.
#include "metrics/engine_agreement.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace st::metrics {
namespace {

// Four pixels in a row: a lit receiver, a shadowed receiver, a surface facing away, the sky.
MeasureSamples fourPixels(float f0, float f1) {
    MeasureSamples s;
    s.width = 4, s.height = 1;
    s.position = {{0, 0, 0, 1}, {1, 0, 0, 1}, {2, 0, 0, 1}, {0, 0, 0, 0}};
    s.normal = {{0, 1, 0, 0.5f}, {0, 1, 0, 0.5f}, {0, 1, 0, -0.5f}, {0, 0, 0, 0}};
    s.geometry = s.normal;
    s.shadow = {{1, f0, 0, 1}, {0, f1, 0, 1}, {0, 0, 0, 1}, {0, 0, -1, 0}};
    return s;
}

TEST(EngineAgreementTest, ScoresReceiversTheEngineDrewOnly) {
    const std::vector<std::uint8_t> truth{1, 0, 0, 0};
    const std::vector<float> soft{1.0f, 0.0f, 0.0f, 0.0f};
    // Model right on both; engine shadows the lit pixel (0.2) and gets the shadow (0.0).
    const std::vector<glm::vec4> engine{{0.2f, 0, 0.5f, 1}, {0.0f, 0, 0.5f, 1}, {1, 0, -0.5f, 1}, {1, -1, 0, 0}};
    std::vector<AgreementClass> classes;
    const EngineAgreement a = compareWithEngine(engine, fourPixels(0.9f, 0.1f), truth, soft, &classes);
    EXPECT_EQ(a.scored, 2u);
    EXPECT_EQ(a.agree, 1u);
    EXPECT_DOUBLE_EQ(a.agreement(), 0.5);
    EXPECT_EQ(a.engineOnlyShadow, 1u);
    EXPECT_EQ(a.modelOnlyShadow, 0u);
    EXPECT_DOUBLE_EQ(a.misclassified(a.engine), 0.5);
    EXPECT_DOUBLE_EQ(a.misclassified(a.model), 0.0);
    EXPECT_NEAR(a.filteredError(a.engine), (0.8 + 0.0) / 2.0, 1e-6);
    EXPECT_NEAR(a.filteredError(a.model), (0.1 + 0.1) / 2.0, 1e-6);
    EXPECT_EQ(classes[0], AgreementClass::EngineOnlyShadow);
    EXPECT_EQ(classes[1], AgreementClass::AgreeShadow);
    EXPECT_EQ(classes[2], AgreementClass::NotScored);
    EXPECT_EQ(classes[3], AgreementClass::NotScored);
}

TEST(EngineAgreementTest, FactorsAHairApartAcrossTheThresholdAreBorderline) {
    // Pixel 0: 0.52 against 0.47, states differ by 0.05 (borderline); pixel 1: 0.9 against 0.1,
    // states differ by 0.8 (a real disagreement).
    const std::vector<glm::vec4> engine{{0.52f, 0, 0.5f, 1}, {0.9f, 0, 0.5f, 1}, {1, 0, -0.5f, 1}, {1, -1, 0, 0}};
    const EngineAgreement a = compareWithEngine(engine, fourPixels(0.47f, 0.1f), {1, 0, 0, 0}, {1.0f, 0.0f, 0.0f, 0.0f});
    EXPECT_EQ(a.agree, 0u);
    EXPECT_EQ(a.borderline, 1u);
    EXPECT_DOUBLE_EQ(a.factorAgreement(), 0.5);
    EXPECT_NEAR(a.meanFactorDifference(), (0.05 + 0.8) / 2.0, 1e-6);
}

TEST(EngineAgreementTest, AReceiverTheEngineDidNotDrawIsCountedApart) {
    const std::vector<glm::vec4> engine{{1, 0, 0.5f, 0}, {0, 0, 0.5f, 1}, {1, 0, 0, 1}, {1, 0, 0, 0}};
    const EngineAgreement a =
        compareWithEngine(engine, fourPixels(0.9f, 0.9f), {1, 0, 0, 0}, {1.0f, 0.0f, 0.0f, 0.0f});
    EXPECT_EQ(a.engineMissing, 1u);
    EXPECT_EQ(a.scored, 1u);
    EXPECT_EQ(a.modelOnlyShadow + a.engineOnlyShadow, 1u);
    EXPECT_EQ(a.model.falseLight, 1u);
    EXPECT_THROW(compareWithEngine({}, fourPixels(1, 1), {1, 0, 0, 0}, {1, 0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace st::metrics
