#include "renderer/csm/splits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::csm {
namespace {

SplitParams paper(float lambda) {  // n = 1, f = 1000, N = 4
    SplitParams p;
    p.count = 4;
    p.nearPlane = 1.0f;
    p.farPlane = 1000.0f;
    p.lambda = lambda;
    return p;
}

void expectNearRel(const std::vector<float>& actual, const std::vector<double>& expected,
                   double rel) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i)
        EXPECT_NEAR(actual[i], expected[i], rel * expected[i]) << "z_" << i;
}

std::string messageOf(const SplitParams& p) {
    try {
        computeSplits(p);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no exception)";
}

// EXPECT_THROW, then the message must name the parameter (and, where given, the value).
void expectRejected(const SplitParams& p, const std::string& name, const std::string& value = "") {
    EXPECT_THROW(computeSplits(p), std::invalid_argument);
    const std::string message = messageOf(p);
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find(value), std::string::npos) << message;
}

TEST(SplitsTest, Lambda0IsUniformHandComputed) {
    // z_i = n + (i/N)(f - n) = 1 + i * 249.75
    expectNearRel(computeSplits(paper(0.0f)), {1.0, 250.75, 500.5, 750.25, 1000.0}, 1e-7);
}

TEST(SplitsTest, Lambda1IsLogarithmicHandComputed) {
    // z_i = n (f/n)^(i/N) = 1000^(i/4)
    expectNearRel(computeSplits(paper(1.0f)), {1.0, 5.6234, 31.623, 177.83, 1000.0}, 5e-5);
}

TEST(SplitsTest, Lambda1IsLogarithmicConstantRatio) {
    // Seed 000 (docs/architecture.md#the-meaning-of-lambda): lambda = 1 is fully logarithmic, so
    // z_{i+1} / z_i is the same for all i.
    SplitParams p = paper(1.0f);
    p.count = 6;
    p.nearPlane = 0.5f;
    p.farPlane = 700.0f;
    const std::vector<float> z = computeSplits(p);
    const double ratio = std::pow(700.0 / 0.5, 1.0 / 6.0);
    for (std::size_t i = 0; i + 1 < z.size(); ++i)
        EXPECT_NEAR(z[i + 1] / z[i], ratio, 1e-5) << "i = " << i;
}

TEST(SplitsTest, LambdaHalfHandComputed) {
    // Average of the two rows above (seed 000: z = 0.5 log + 0.5 uniform):
    //   z_1 = (5.623413 + 250.75) / 2 = 128.186707
    //   z_2 = (31.622777 + 500.5) / 2 = 266.061388
    //   z_3 = (177.827941 + 750.25) / 2 = 464.038971
    expectNearRel(computeSplits(paper(0.5f)), {1.0, 128.186707, 266.061388, 464.038971, 1000.0},
                  1e-6);
}

TEST(SplitsTest, SchemesAreLambdaShortcuts) {
    SplitParams p = paper(0.3f);
    p.scheme = SplitScheme::Uniform;
    EXPECT_EQ(computeSplits(p), computeSplits(paper(0.0f)));
    p.scheme = SplitScheme::Logarithmic;
    EXPECT_EQ(computeSplits(p), computeSplits(paper(1.0f)));
}

TEST(SplitsTest, RandomParametersAreMonotonicWithExactEnds) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 2000; ++trial) {
        SplitParams p;
        p.scheme = static_cast<SplitScheme>(trial % 3);  // Uniform, Logarithmic, Practical
        p.count = 1 + trial % 8;
        p.nearPlane = 0.01f + 10.0f * unit(rng);
        p.farPlane = p.nearPlane * std::exp(std::log(1.5f) + unit(rng) * std::log(1e4f / 1.5f));
        p.lambda = unit(rng);
        const bool cut = trial % 2 == 1;
        p.shadowDistance = cut ? p.nearPlane + (p.farPlane - p.nearPlane) * (0.1f + 0.9f * unit(rng))
                               : 0.0f;
        const std::vector<float> z = computeSplits(p);
        ASSERT_EQ(z.size(), static_cast<std::size_t>(p.count) + 1);
        EXPECT_EQ(z.front(), p.nearPlane);
        EXPECT_EQ(z.back(), cut ? p.shadowDistance : p.farPlane);
        for (std::size_t i = 0; i + 1 < z.size(); ++i)
            ASSERT_LT(z[i], z[i + 1]) << "trial " << trial << " i " << i;
    }
}

TEST(SplitsTest, ShadowDistanceShorterThanFarEndsThere) {
    SplitParams p = paper(0.0f);
    p.shadowDistance = 401.0f;
    // Uniform over [1, 401]: steps of 100.
    EXPECT_EQ(computeSplits(p), (std::vector<float>{1.0f, 101.0f, 201.0f, 301.0f, 401.0f}));
}

TEST(SplitsTest, ManualGivesExactlyTheManualValues) {
    // Seed 001: near 0.1, far 1000, cascades end at 20, 80 and a shadow distance of 400.
    const std::vector<float> manual = {20.0f, 80.0f};
    SplitParams p;
    p.scheme = SplitScheme::Manual;
    p.count = 3;
    p.nearPlane = 0.1f;
    p.farPlane = 1000.0f;
    p.manual = manual;
    p.shadowDistance = 400.0f;
    EXPECT_EQ(computeSplits(p), (std::vector<float>{0.1f, 20.0f, 80.0f, 400.0f}));
}

TEST(SplitsTest, RejectsNearNotLessThanFar) {
    SplitParams p = paper(0.5f);
    p.nearPlane = 5.0f;
    p.farPlane = 1.0f;
    expectRejected(p, "nearPlane", "(5)");
    p.farPlane = 5.0f;
    expectRejected(p, "farPlane", "(5)");
    p.nearPlane = 0.0f;
    expectRejected(p, "nearPlane", "got 0");
}

TEST(SplitsTest, RejectsCountOutside1To8) {
    SplitParams p = paper(0.5f);
    p.count = 0;
    expectRejected(p, "cascades.count", "got 0");
    p.count = 9;
    expectRejected(p, "cascades.count", "got 9");
}

TEST(SplitsTest, RejectsLambdaOutside01) {
    SplitParams p = paper(1.5f);
    expectRejected(p, "cascades.lambda", "1.5");
    p.lambda = -0.1f;
    expectRejected(p, "cascades.lambda", "-0.1");
}

TEST(SplitsTest, RejectsBadManualSplits) {
    SplitParams p = paper(0.5f);
    p.scheme = SplitScheme::Manual;
    const std::vector<float> decreasing = {300.0f, 200.0f, 100.0f};
    p.manual = decreasing;
    expectRejected(p, "cascades.manualSplits", "200");
    const std::vector<float> tooFew = {100.0f, 200.0f};
    p.manual = tooFew;
    expectRejected(p, "cascades.manualSplits", "got 2");
    const std::vector<float> pastEnd = {100.0f, 200.0f, 1000.0f};
    p.manual = pastEnd;
    expectRejected(p, "cascades.manualSplits", "1000");
}

TEST(SplitsTest, RejectsShadowDistanceBeyondFar) {
    SplitParams p = paper(0.5f);
    p.shadowDistance = 1500.0f;
    expectRejected(p, "cascades.shadowDistance", "1500");
    p.shadowDistance = 0.5f;  // inside the near plane
    expectRejected(p, "cascades.shadowDistance", "0.5");
}

}  // namespace
}  // namespace st::csm
