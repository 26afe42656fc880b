#pragma once
// The cost model (docs/cost-model.md): modelled milliseconds per pass as a non-negative linear
// function of the work the pass did (renderer/render/pass_work.h), with coefficients fitted on
// one machine by `shadowtune calibrate` and kept in a profile. Counted work is identical in every
// run, so the modelled cost is too: fronts and charts stop moving with the machine's load.
// Pure code, no GL.
#include "renderer/render/frame_stats.h"
#include "renderer/render/pass_work.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace st::metrics {

// The passes the timers separate (FrameStats::cascades[i].gpuMs, gpuMainMs, gpuFilterMs,
// gpuDepthBoundsMs). Each cascade's depth pass is one sample of the Cascade kind.
enum class PassKind { Cascade, Main, Filter, DepthBounds };
inline constexpr std::array<PassKind, 4> kPassKinds{PassKind::Cascade, PassKind::Main, PassKind::Filter,
                                                    PassKind::DepthBounds};
const char* passKindName(PassKind k);  // "cascade", "main", "filter", "depthBounds"
std::optional<PassKind> passKindFromName(std::string_view name);

// A model term: PassWork's counters; Intercept, 1 for a pass that did any work (a kept map, or a
// filter that does not run, costs nothing); and LargeMapFragments, the fragments of a pass whose
// target holds at least kLargeMapTexels (a cascade's map of 2048² or more), which on llvmpipe cost
// more each than a smaller map's (docs/cost-model.md#large-maps).
enum class Feature {
    Intercept, Draws, Vertices, Primitives, ClippedPrimitives, Fragments, SamplesPassed, ComputeInvocations,
    TexelsCleared, FilterTaps, BytesRead, BytesWritten, LargeMapFragments
};
inline constexpr std::array<Feature, 13> kFeatures{
    Feature::Intercept, Feature::Draws, Feature::Vertices, Feature::Primitives, Feature::ClippedPrimitives,
    Feature::Fragments, Feature::SamplesPassed, Feature::ComputeInvocations, Feature::TexelsCleared, Feature::FilterTaps,
    Feature::BytesRead, Feature::BytesWritten, Feature::LargeMapFragments};
inline constexpr std::uint64_t kLargeMapTexels = 2048u * 2048u;
const char* featureName(Feature f);  // PassWork's member names; "intercept"
std::optional<Feature> featureFromName(std::string_view name);
double featureValue(const PassWork& w, Feature f);
bool didWork(const PassWork& w);

// The features calibration fits for each kind of pass on a rasteriser like llvmpipe's
// (docs/cost-model.md says why these and not the others).
std::vector<Feature> defaultFeatures(PassKind k);

struct Term {
    Feature feature = Feature::Intercept;
    double msPerUnit = 0.0;  // >= 0
    bool operator==(const Term&) const = default;
};

struct PassModel {
    std::vector<Term> terms;  // empty: the pass kind was never seen in calibration; models 0 ms
    double r2 = 0.0;          // of the fit on its calibration samples
    int samples = 0;
    // Machine and date of a kind refitted on its own after the profile's calibration
    // (refitOnOwnTimers, `calibrate --refit`); empty: the profile's own machine and date.
    std::string calibrated;
    bool operator==(const PassModel&) const = default;
};

// One calibration sample as fitted: measured over the frames, and modelled by the profile.
struct Residual {
    std::string preset;
    std::string pass;  // "cascade 2", "main", "filter", "depthBounds"
    double minMs = 0.0;
    double medianMs = 0.0;
    double modelMs = 0.0;
    bool operator==(const Residual&) const = default;
};

struct CostProfile {
    std::string renderer;  // GL_RENDERER of the calibrated machine
    std::string machine;   // CPU model and cores, or the GPU
    std::string date;      // ISO 8601 UTC of the calibration
    int frames = 0;        // timed frames per preset
    std::string fittedOn = "frame minimum";  // which of the frames' times the coefficients were fitted on
    double frameR2 = 0.0;  // of the modelled frame totals against the measured ones (the fitted figure)
    std::array<PassModel, 4> passes;  // by PassKind
    std::vector<Residual> residuals;
    PassModel& pass(PassKind k) { return passes[std::size_t(k)]; }
    const PassModel& pass(PassKind k) const { return passes[std::size_t(k)]; }
    bool operator==(const CostProfile&) const = default;
};

struct ModelledCost {
    std::vector<double> cascadesMs;  // per cascade; 0 for a kept map
    double shadowMs = 0.0;           // their sum
    double mainMs = 0.0;
    double filterMs = 0.0;
    double depthBoundsMs = 0.0;
    double totalMs = 0.0;
};

double modelPass(const PassModel& m, const PassWork& w);  // 0 for a pass that did no work
ModelledCost modelFrame(const CostProfile& p, const FrameWork& w);
// The work of a frame in which every map is redrawn: `stats.work` with each kept map's work taken
// from its last redraw (CascadeStats::drawnWork). What the settings cost, not what this frame
// happened to skip; the editor's labels model this.
FrameWork withEveryMapRedrawn(const FrameStats& stats);
// How outputs name a profile: "llvmpipe (LLVM 15.0.6, 256 bits), calibrated 2026-12-01".
std::string profileName(const CostProfile& p);

// What calibration measured for one pass of one preset.
struct CalibrationSample {
    std::string preset;
    PassKind kind = PassKind::Main;
    std::string pass;  // as Residual::pass
    PassWork work;
    double minMs = 0.0;
    double medianMs = 0.0;
};

struct FitOptions {
    // Minimise relative rather than absolute error: each sample's row is divided by
    // max(measured, floorMs), so a 2 ms pass counts as much as a 200 ms one (the goal is a
    // median relative error) without letting a near-zero timing dominate.
    bool relative = true;
    double floorMs = 1.0;
};

// Fits `features` to the samples' minimum times by non-negative least squares (metrics/nnls.h);
// R² is of the fitted times against the minimum times, unweighted. Samples that did no work are
// left out (they model 0 whatever the coefficients). No samples: an empty model.
PassModel fitPass(const std::vector<Feature>& features, const std::vector<CalibrationSample>& samples,
                  const FitOptions& opt = {});

// Each kind fitted on its own samples with defaultFeatures(kind), and the residuals of all.
// The caller fills renderer, machine, date and frames.
CostProfile fitProfile(const std::vector<CalibrationSample>& samples, const FitOptions& opt = {});

// What calibration measured for one frame: its counted work and its total GPU time (all passes).
struct CalibrationFrame {
    std::string preset;
    FrameWork work;
    double minMs = 0.0;
    double medianMs = 0.0;
};

// The kinds fitted on their own pass timers rather than on frame totals: the depth-bounds pass
// (3.6-7.2 ms on llvmpipe at 640x360, 2026-12-03) is a few per cent of its frames, less than the
// other kinds' model error on those frames, so fitted on frame totals it took their residual as
// its own (the profile of 2026-12-02 priced truck-town's 4.4 ms pass at 22.9 ms). Its timer
// agrees with the frame difference it makes (docs/cost-model.md), unlike some cascades'.
bool fittedOnOwnTimers(PassKind k);

// All kinds' defaultFeatures fitted jointly on the frames' minimum totals: one row per frame,
// one column per (kind, feature), holding the feature summed over the frame's passes of that
// kind. What calibration fits: llvmpipe's per-pass timers are not a clean target (in this
// machine's calibration some cascades read 0.00 ms for a million-fragment pass and the moment
// filter read ~1 s; docs/cost-model.md), while the frame total is whole and is what fronts rank.
// Each kind's R² is of its modelled pass times against `passes`' timers (per-pass figures,
// for the record); frameR2 is the fit's. Residuals: each frame ("frame"), then each pass.
// The kinds fittedOnOwnTimers are fitted first on their passes' timers (fitPass), and the
// frames' targets are their totals less those kinds' modelled passes.
CostProfile fitProfileOnFrames(const std::vector<CalibrationFrame>& frames,
                               const std::vector<CalibrationSample>& passes, const FitOptions& opt = {});

// `base` with kind k refitted on `samples` (its passes' timers; other kinds' samples ignored),
// every other kind's coefficients kept, k's residuals replaced, and `calibrated` recorded on k.
// Only for the kinds fittedOnOwnTimers (throws std::invalid_argument for another: those are
// fitted jointly, and one refitted alone would stop summing to the frames it was fitted on).
CostProfile refitOnOwnTimers(CostProfile base, PassKind k, const std::vector<CalibrationSample>& samples,
                             const std::string& calibrated, const FitOptions& opt = {});

}  // namespace st::metrics
