// The cost model's numerics: NNLS, R², Spearman, the relative error, modelFrame, the fit, and
// the profile's JSON. Every expectation is computed by hand or from data built with known
// coefficients.
#include "metrics/cost_model.h"
#include "metrics/cost_profile_json.h"
#include "metrics/model_error.h"
#include "metrics/nnls.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace st::metrics {
namespace {

// Exact data from known coefficients over columns of very different scales (1, ~1e3, ~1e6),
// as the cost features are.
TEST(NnlsTest, RecoversKnownCoefficientsFromExactData) {
    const std::vector<double> truth{0.75, 2e-3, 4e-6};
    Matrix a;
    std::vector<double> b;
    for (int i = 0; i < 12; ++i) {
        const std::vector<double> row{1.0, 100.0 + 97.0 * i, 1e5 * (1 + (i * 7) % 11)};
        a.push_back(row);
        b.push_back(truth[0] * row[0] + truth[1] * row[1] + truth[2] * row[2]);
    }
    const std::vector<double> x = nnls(a, b);
    ASSERT_EQ(x.size(), 3u);
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(x[j], truth[j], 1e-9 * truth[j] + 1e-15) << j;
}

// b = 3 col0 - 1 col1: the unconstrained fit gives col1 a negative coefficient. With col1 held at
// 0 the best col0 is (col0 . b) / (col0 . col0) = mean(b) = 1.5, and the residual's gradient toward
// col1, col1 . (b - 1.5 col0) = 0.5 - 1 - 4.5, points out of the feasible side (Kuhn-Tucker).
TEST(NnlsTest, KeepsCoefficientsNonNegative) {
    const Matrix a{{1, 0}, {1, 1}, {1, 2}, {1, 3}};
    const std::vector<double> b{3, 2, 1, 0};
    const std::vector<double> free = leastSquares(a, b);
    ASSERT_NEAR(free[0], 3.0, 1e-12);
    ASSERT_NEAR(free[1], -1.0, 1e-12);
    const std::vector<double> x = nnls(a, b);
    EXPECT_EQ(x[1], 0.0);
    EXPECT_NEAR(x[0], 1.5, 1e-12);
    EXPECT_EQ(nnls(a, {-1, -2, -3, -4}), (std::vector<double>{0.0, 0.0}));  // nothing positive explains it
}

TEST(NnlsTest, ClampsOneColumnAndFitsTheOther) {
    // b rises with col0 and falls with col1; only col0 may explain it.
    const Matrix a{{1, 3}, {2, 2}, {3, 1}, {4, 0}};
    const std::vector<double> b{1, 2, 3, 4};  // = col0 exactly
    const std::vector<double> x = nnls(a, {2, 3, 4, 5});  // col0 + 1, col1 cannot help (col1 = 4 - col0)
    EXPECT_GE(x[0], 0.0);
    EXPECT_GE(x[1], 0.0);
    const std::vector<double> exact = nnls(a, b);
    EXPECT_NEAR(exact[0], 1.0, 1e-12);
    EXPECT_NEAR(exact[1], 0.0, 1e-12);
    // col0 + 1 = 1.25 col0 + 0.25 col1 exactly, with both non-negative.
    EXPECT_NEAR(x[0], 1.25, 1e-12);
    EXPECT_NEAR(x[1], 0.25, 1e-12);
}

TEST(NnlsTest, RSquared) {
    EXPECT_DOUBLE_EQ(rSquared({1, 2, 3}, {1, 2, 3}), 1.0);
    // mean 2, SStot = 2, SSres = 0.25 + 0 + 0.25 = 0.5
    EXPECT_DOUBLE_EQ(rSquared({1, 2, 3}, {1.5, 2, 2.5}), 0.75);
}

TEST(ModelErrorTest, SpearmanWithTies) {
    // Ranks of a: 1, 2.5, 2.5, 4; of b: 1, 2, 3, 4 (means 2.5). Deviations a: -1.5, 0, 0, 1.5;
    // b: -1.5, -0.5, 0.5, 1.5. Sab = 4.5, Saa = 4.5, Sbb = 5: rho = 4.5 / sqrt(22.5).
    EXPECT_NEAR(spearman({1, 2, 2, 3}, {10, 20, 30, 40}), 4.5 / std::sqrt(22.5), 1e-12);
    EXPECT_EQ(fractionalRanks({5, 1, 5, 5}), (std::vector<double>{3, 1, 3, 3}));
    EXPECT_NEAR(spearman({1, 2, 3}, {30, 20, 10}), -1.0, 1e-12);
    EXPECT_EQ(spearman({1, 1, 1}, {1, 2, 3}), 0.0);
}

TEST(ModelErrorTest, MedianRelativeErrorSkipsZeroMeasurements) {
    // |1.1-1|/1 = 0.1, 0, |2.7-3|/3 = 0.1; the zero measurement has no relative error.
    EXPECT_NEAR(medianRelativeError({1.1, 2, 2.7, 5}, {1, 2, 3, 0}), 0.1, 1e-12);
    EXPECT_NEAR(medianRelativeError({2, 4}, {1, 1}), 2.0, 1e-12);  // mean of 1 and 3
}

PassWork work(std::uint64_t vertices, std::uint64_t fragments, std::uint64_t cleared = 0) {
    PassWork w;
    w.draws = 1;
    w.vertices = vertices;
    w.primitives = vertices / 3;
    w.clippedPrimitives = vertices / 3;
    w.fragments = fragments;
    w.texelsCleared = cleared;
    return w;
}

CostProfile knownProfile() {
    CostProfile p;
    p.renderer = "llvmpipe (test)";
    p.machine = "test machine, 2 cores";
    p.date = "2026-12-01T00:00:00Z";
    p.frames = 3;
    p.pass(PassKind::Cascade).terms = {{Feature::Intercept, 0.5}, {Feature::Fragments, 1e-6},
                                       {Feature::TexelsCleared, 2e-7}};
    p.pass(PassKind::Main).terms = {{Feature::Intercept, 1.0}, {Feature::ClippedPrimitives, 3e-4},
                                    {Feature::Fragments, 3e-6}};
    p.frameR2 = 0.9375;
    p.pass(PassKind::Main).r2 = 0.875;
    p.pass(PassKind::Main).samples = 7;
    p.residuals = {{"default", "main", 2.5, 2.75, 2.625}, {"fox", "cascade 1", 0.25, 0.5, 0.375}};
    return p;
}

TEST(CostModelTest, ModelFrameByHand) {
    FrameWork w;
    w.cascades = {work(300, 1'000'000, 4'000'000), PassWork{}};  // the second map kept
    w.main = work(3000, 2'000'000);
    const ModelledCost c = modelFrame(knownProfile(), w);
    ASSERT_EQ(c.cascadesMs.size(), 2u);
    EXPECT_NEAR(c.cascadesMs[0], 0.5 + 1.0 + 0.8, 1e-12);
    EXPECT_EQ(c.cascadesMs[1], 0.0);
    EXPECT_NEAR(c.shadowMs, 2.3, 1e-12);
    EXPECT_NEAR(c.mainMs, 1.0 + 0.3 + 6.0, 1e-12);
    EXPECT_EQ(c.filterMs, 0.0);  // no filter work, and no filter coefficients
    EXPECT_NEAR(c.totalMs, 2.3 + 7.3, 1e-12);
}

TEST(CostModelTest, EveryFeatureHasItsNameAndItsCounter) {
    for (Feature f : kFeatures) EXPECT_EQ(featureFromName(featureName(f)), f) << featureName(f);
    EXPECT_EQ(featureFromName("samplesPassed"), Feature::SamplesPassed);
    PassWork w;
    w.fragments = 5000;
    w.samplesPassed = 1234;
    EXPECT_EQ(featureValue(w, Feature::SamplesPassed), 1234.0);
    EXPECT_EQ(featureValue(w, Feature::Fragments), 5000.0);
}

// A map of 2048² or more prices its fragments twice: as fragments, and as a large map's.
TEST(CostModelTest, LargeMapFragmentsAreTheFragmentsOfMapsOf2048SquaredOrMore) {
    PassWork w;
    w.fragments = 5000;
    w.texelsCleared = 1024u * 1024u;
    EXPECT_EQ(featureValue(w, Feature::LargeMapFragments), 0.0);
    w.texelsCleared = 2048u * 2048u - 1u;
    EXPECT_EQ(featureValue(w, Feature::LargeMapFragments), 0.0);
    w.texelsCleared = 2048u * 2048u;
    EXPECT_EQ(featureValue(w, Feature::LargeMapFragments), 5000.0);
    EXPECT_EQ(featureFromName("largeMapFragments"), Feature::LargeMapFragments);
    const std::vector<Feature> cascade = defaultFeatures(PassKind::Cascade);
    EXPECT_NE(std::find(cascade.begin(), cascade.end(), Feature::LargeMapFragments), cascade.end());
    CostProfile p;
    p.pass(PassKind::Cascade).terms = {{Feature::Fragments, 1e-6}, {Feature::LargeMapFragments, 5e-7}};
    FrameWork f;
    f.cascades = {w};
    EXPECT_NEAR(modelFrame(p, f).shadowMs, 5000 * 1.5e-6, 1e-15);
}

// A profile written before samplesPassed was counted has no term for it: it loads and models
// the work it knows, whatever samplesPassed says; a profile with the term prices it.
TEST(CostModelTest, SamplesPassedIsPricedOnlyByProfilesThatHaveIt) {
    PassWork m = work(3000, 2'000'000);
    const double without = modelFrame(knownProfile(), FrameWork{.main = m}).mainMs;
    m.samplesPassed = 500'000;
    EXPECT_EQ(modelFrame(knownProfile(), FrameWork{.main = m}).mainMs, without);
    CostProfile p = knownProfile();
    p.pass(PassKind::Main).terms.push_back({Feature::SamplesPassed, 2e-6});
    EXPECT_NEAR(modelFrame(p, FrameWork{.main = m}).mainMs, without + 1.0, 1e-12);
    nlohmann::ordered_json j = toJson(p);
    EXPECT_EQ(j["passes"]["main"]["coefficients"]["samplesPassed"], 2e-6);
    EXPECT_EQ(costProfileFromJson(j, "mem"), p);
    j["passes"]["main"]["coefficients"].erase("samplesPassed");
    EXPECT_EQ(costProfileFromJson(j, "mem"), knownProfile());
}

TEST(CostModelTest, FitRecoversCoefficientsOfExactSamples) {
    const CostProfile truth = knownProfile();
    std::vector<CalibrationSample> samples;
    for (int i = 1; i <= 8; ++i) {
        const PassWork c = work(300u * i, 150'000u * std::uint64_t((i * 5) % 9 + 1), 1'048'576u * std::uint64_t(1 + i % 3));
        const PassWork m = work(1000u * std::uint64_t((i * 3) % 7 + 1), 200'000u * std::uint64_t(i));
        const double cMs = modelPass(truth.pass(PassKind::Cascade), c), mMs = modelPass(truth.pass(PassKind::Main), m);
        samples.push_back({"p" + std::to_string(i), PassKind::Cascade, "cascade 0", c, cMs, cMs * 1.1});
        samples.push_back({"p" + std::to_string(i), PassKind::Main, "main", m, mMs, mMs});
    }
    const CostProfile p = fitProfile(samples);
    EXPECT_EQ(p.pass(PassKind::Cascade).samples, 8);
    EXPECT_EQ(p.pass(PassKind::Filter).samples, 0);
    EXPECT_TRUE(p.pass(PassKind::Filter).terms.empty());
    EXPECT_NEAR(p.pass(PassKind::Main).r2, 1.0, 1e-9);
    EXPECT_NEAR(p.pass(PassKind::Cascade).r2, 1.0, 1e-9);
    ASSERT_EQ(p.residuals.size(), samples.size());
    for (const Residual& r : p.residuals) EXPECT_NEAR(r.modelMs, r.minMs, 1e-9 * r.minMs) << r.preset << " " << r.pass;
    EXPECT_EQ(p.residuals[0].medianMs, samples[0].medianMs);
}

// Frames whose total is exactly the known profile's: the joint fit reproduces every total, and
// the kinds no frame had get no terms.
TEST(CostModelTest, FitOnFramesReproducesExactTotals) {
    const CostProfile truth = knownProfile();
    std::vector<CalibrationFrame> frames;
    std::vector<CalibrationSample> passes;
    for (int i = 1; i <= 10; ++i) {
        FrameWork w;
        for (int c = 0; c < 1 + i % 4; ++c)
            w.cascades.push_back(work(300u * std::uint64_t(i + c), 150'000u * std::uint64_t((i * 5 + c) % 9 + 1),
                                      262'144u * std::uint64_t(1 + (i + c) % 4)));
        w.main = work(999u * std::uint64_t((i * 3) % 7 + 1), 57'600u * std::uint64_t(i));
        const double ms = modelFrame(truth, w).totalMs;
        frames.push_back({"p" + std::to_string(i), w, ms, ms * 1.2});
        passes.push_back({"p" + std::to_string(i), PassKind::Main, "main", w.main, 1.0, 1.0});
    }
    const CostProfile p = fitProfileOnFrames(frames, passes);
    EXPECT_NEAR(p.frameR2, 1.0, 1e-9);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        EXPECT_EQ(p.residuals[i].pass, "frame");
        EXPECT_NEAR(p.residuals[i].modelMs, frames[i].minMs, 1e-6 * frames[i].minMs) << i;
        EXPECT_EQ(p.residuals[i].medianMs, frames[i].medianMs);
    }
    EXPECT_EQ(p.residuals.size(), frames.size() + passes.size());
    EXPECT_EQ(p.pass(PassKind::Main).samples, 10);
    EXPECT_TRUE(p.pass(PassKind::Filter).terms.empty());
    for (PassKind k : kPassKinds)
        for (const Term& t : p.pass(k).terms) EXPECT_GE(t.msPerUnit, 0.0);
}

// A depth-bounds pass of a few ms in frames whose other passes the model misses by more: fitted
// on frame totals its coefficients took that miss; fitted on its own timers they are its own.
TEST(CostModelTest, DepthBoundsIsFittedOnItsOwnTimersNotOnTheFramesMiss) {
    CostProfile truth = knownProfile();
    truth.pass(PassKind::DepthBounds).terms = {{Feature::Intercept, 0.25}, {Feature::Draws, 0.0},
                                               {Feature::ClippedPrimitives, 0.0}, {Feature::Fragments, 2e-6},
                                               {Feature::ComputeInvocations, 1e-4}};
    std::vector<CalibrationFrame> frames;
    std::vector<CalibrationSample> passes;
    for (int i = 1; i <= 12; ++i) {
        FrameWork w;
        w.cascades.push_back(work(300u * std::uint64_t(i), 150'000u * std::uint64_t(i % 5 + 1), 1'048'576u));
        w.main = work(999u * std::uint64_t(i % 7 + 1), 57'600u * std::uint64_t(i));
        if (i % 3 == 0) {
            w.depthBounds = work(999u * std::uint64_t(i % 7 + 1), 20'000u * std::uint64_t(i));
            w.depthBounds.computeInvocations = 3600u * std::uint64_t(i);
        }
        // The frames with the prepass run 10 % over their modelled cascades and main pass.
        const ModelledCost m = modelFrame(truth, w);
        const double miss = didWork(w.depthBounds) ? 0.1 * (m.shadowMs + m.mainMs) : 0.0;
        frames.push_back({"p" + std::to_string(i), w, m.totalMs + miss, m.totalMs + miss});
        if (didWork(w.depthBounds))
            passes.push_back({"p" + std::to_string(i), PassKind::DepthBounds, "depthBounds", w.depthBounds,
                              m.depthBoundsMs, m.depthBoundsMs});
    }
    EXPECT_TRUE(fittedOnOwnTimers(PassKind::DepthBounds));
    const CostProfile p = fitProfileOnFrames(frames, passes);
    EXPECT_EQ(p.pass(PassKind::DepthBounds).samples, 4);
    EXPECT_NEAR(p.pass(PassKind::DepthBounds).r2, 1.0, 1e-9);
    for (const CalibrationSample& s : passes)
        EXPECT_NEAR(modelPass(p.pass(PassKind::DepthBounds), s.work), s.minMs, 1e-6 * s.minMs) << s.preset;
}

// --refit: only the named kind's coefficients and residuals change, and where it was fitted is
// recorded on it and kept through JSON; a jointly fitted kind cannot be refitted alone.
TEST(CostModelTest, RefitChangesOnlyItsKindAndSaysWhere) {
    const CostProfile base = knownProfile();
    std::vector<CalibrationSample> samples;
    for (int i = 1; i <= 6; ++i) {
        PassWork w = work(600u * std::uint64_t(i), 40'000u * std::uint64_t(i * i));
        w.computeInvocations = 1000u * std::uint64_t(7 - i);
        const double ms = 0.5 + 1e-6 * double(w.fragments) + 2e-4 * double(w.computeInvocations);
        samples.push_back({"q" + std::to_string(i), PassKind::DepthBounds, "depthBounds", w, ms, ms});
        samples.push_back({"q" + std::to_string(i), PassKind::Main, "main", work(9, 9), 99.0, 99.0});
    }
    const CostProfile p = refitOnOwnTimers(base, PassKind::DepthBounds, samples, "test machine B, 2026-12-03");
    for (PassKind k : {PassKind::Cascade, PassKind::Main, PassKind::Filter}) EXPECT_EQ(p.pass(k), base.pass(k));
    EXPECT_EQ(p.pass(PassKind::DepthBounds).samples, 6);
    EXPECT_EQ(p.pass(PassKind::DepthBounds).calibrated, "test machine B, 2026-12-03");
    ASSERT_EQ(p.residuals.size(), base.residuals.size() + 6);
    for (std::size_t i = 0; i < base.residuals.size(); ++i) EXPECT_EQ(p.residuals[i], base.residuals[i]);
    for (std::size_t i = base.residuals.size(); i < p.residuals.size(); ++i)
        EXPECT_NEAR(p.residuals[i].modelMs, p.residuals[i].minMs, 1e-6 * p.residuals[i].minMs) << i;
    EXPECT_EQ(costProfileFromJson(toJson(p), "mem"), p);
    EXPECT_EQ(refitOnOwnTimers(p, PassKind::DepthBounds, samples, "again").residuals.size(), p.residuals.size());
    EXPECT_THROW(refitOnOwnTimers(base, PassKind::Main, samples, "x"), std::invalid_argument);
}

TEST(CostProfileJsonTest, RoundTrip) {
    const CostProfile p = knownProfile();
    const std::string text = toJson(p).dump(2);
    EXPECT_EQ(costProfileFromJson(nlohmann::ordered_json::parse(text), "mem"), p);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("st-cost-profile-" + std::to_string(::getpid()) + ".json");
    saveCostProfileAtomic(p, file);
    EXPECT_EQ(loadCostProfile(file), p);
    std::filesystem::remove(file);
}

std::string errorOf(const nlohmann::ordered_json& j) {
    try {
        costProfileFromJson(j, "bad.json");
    } catch (const CostProfileError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CostProfileJsonTest, MalformedProfileNamesTheJsonPath) {
    nlohmann::ordered_json j = toJson(knownProfile());
    j["passes"]["main"]["coefficients"]["vertices"] = "fast";
    EXPECT_EQ(errorOf(j), "bad.json: passes.main.coefficients.vertices: expected a number, got string");
    j = toJson(knownProfile());
    j["passes"]["cascade"]["coefficients"]["fragments"] = -1.0;
    EXPECT_NE(errorOf(j).find("bad.json: passes.cascade.coefficients.fragments: "), std::string::npos) << errorOf(j);
    j = toJson(knownProfile());
    j["passes"]["main"]["coefficients"]["pixels"] = 1.0;
    EXPECT_NE(errorOf(j).find("passes.main.coefficients.pixels: unknown feature"), std::string::npos) << errorOf(j);
    j = toJson(knownProfile());
    j["residuals"][1].erase("modelMs");
    EXPECT_EQ(errorOf(j), "bad.json: residuals[1].modelMs: missing");
    j = toJson(knownProfile());
    j.erase("renderer");
    EXPECT_EQ(errorOf(j), "bad.json: renderer: missing");
}

TEST(CostProfileJsonTest, UnreadableFileIsAnError) {
    EXPECT_THROW(loadCostProfile("/nonexistent/profile.json"), CostProfileError);
}

}  // namespace
}  // namespace st::metrics
