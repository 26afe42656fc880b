#include "metrics/cost_model.h"

#include "metrics/nnls.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace st::metrics {

const char* passKindName(PassKind k) {
    switch (k) {
        case PassKind::Cascade: return "cascade";
        case PassKind::Main: return "main";
        case PassKind::Filter: return "filter";
        case PassKind::DepthBounds: return "depthBounds";
    }
    return "?";
}

std::optional<PassKind> passKindFromName(std::string_view name) {
    for (PassKind k : kPassKinds)
        if (name == passKindName(k)) return k;
    return std::nullopt;
}

const char* featureName(Feature f) {
    switch (f) {
        case Feature::Intercept: return "intercept";
        case Feature::Draws: return "draws";
        case Feature::Vertices: return "vertices";
        case Feature::Primitives: return "primitives";
        case Feature::ClippedPrimitives: return "clippedPrimitives";
        case Feature::Fragments: return "fragments";
        case Feature::SamplesPassed: return "samplesPassed";
        case Feature::ComputeInvocations: return "computeInvocations";
        case Feature::TexelsCleared: return "texelsCleared";
        case Feature::FilterTaps: return "filterTaps";
        case Feature::BytesRead: return "bytesRead";
        case Feature::BytesWritten: return "bytesWritten";
        case Feature::LargeMapFragments: return "largeMapFragments";
    }
    return "?";
}

std::optional<Feature> featureFromName(std::string_view name) {
    for (Feature f : kFeatures)
        if (name == featureName(f)) return f;
    return std::nullopt;
}

bool didWork(const PassWork& w) { return !(w == PassWork{}); }

double featureValue(const PassWork& w, Feature f) {
    switch (f) {
        case Feature::Intercept: return didWork(w) ? 1.0 : 0.0;
        case Feature::Draws: return double(w.draws);
        case Feature::Vertices: return double(w.vertices);
        case Feature::Primitives: return double(w.primitives);
        case Feature::ClippedPrimitives: return double(w.clippedPrimitives);
        case Feature::Fragments: return double(w.fragments);
        case Feature::SamplesPassed: return double(w.samplesPassed);
        case Feature::ComputeInvocations: return double(w.computeInvocations);
        case Feature::TexelsCleared: return double(w.texelsCleared);
        case Feature::FilterTaps: return double(w.filterTaps);
        case Feature::BytesRead: return double(w.bytesRead);
        case Feature::BytesWritten: return double(w.bytesWritten);
        case Feature::LargeMapFragments: return w.texelsCleared >= kLargeMapTexels ? double(w.fragments) : 0.0;
    }
    return 0.0;
}

std::vector<Feature> defaultFeatures(PassKind k) {
    using F = Feature;
    switch (k) {
        case PassKind::Cascade:
            return {F::Intercept, F::Draws, F::ClippedPrimitives, F::Fragments, F::TexelsCleared, F::LargeMapFragments};
        case PassKind::Main: return {F::Intercept, F::Draws, F::ClippedPrimitives, F::Fragments, F::SamplesPassed, F::FilterTaps};
        case PassKind::Filter: return {F::Intercept, F::ClippedPrimitives, F::Fragments, F::FilterTaps};
        // A depth-only draw of the main pass's geometry (per draw, per primitive, per fragment, as
        // a cascade), then the reduction's compute invocations.
        case PassKind::DepthBounds:
            return {F::Intercept, F::Draws, F::ClippedPrimitives, F::Fragments, F::ComputeInvocations};
    }
    return {};
}

double modelPass(const PassModel& m, const PassWork& w) {
    if (!didWork(w)) return 0.0;
    double ms = 0.0;
    for (const Term& t : m.terms) ms += t.msPerUnit * featureValue(w, t.feature);
    return ms;
}

FrameWork withEveryMapRedrawn(const FrameStats& stats) {
    FrameWork w = stats.work;
    w.cascades.clear();
    w.shadow = PassWork{};
    for (const CascadeStats& c : stats.cascades) {
        w.cascades.push_back(c.drawnWork);
        w.shadow += c.drawnWork;
    }
    return w;
}

std::string profileName(const CostProfile& p) {
    std::string name = p.renderer.empty() ? std::string("unnamed renderer") : p.renderer;
    if (!p.date.empty()) name += ", calibrated " + p.date.substr(0, 10);
    return name;
}

ModelledCost modelFrame(const CostProfile& p, const FrameWork& w) {
    ModelledCost c;
    for (const PassWork& cascade : w.cascades) {
        c.cascadesMs.push_back(modelPass(p.pass(PassKind::Cascade), cascade));
        c.shadowMs += c.cascadesMs.back();
    }
    c.mainMs = modelPass(p.pass(PassKind::Main), w.main);
    c.filterMs = modelPass(p.pass(PassKind::Filter), w.filter);
    c.depthBoundsMs = modelPass(p.pass(PassKind::DepthBounds), w.depthBounds);
    c.totalMs = c.shadowMs + c.mainMs + c.filterMs + c.depthBoundsMs;
    return c;
}

PassModel fitPass(const std::vector<Feature>& features, const std::vector<CalibrationSample>& samples,
                  const FitOptions& opt) {
    Matrix a;
    std::vector<double> b, measured;
    std::vector<const CalibrationSample*> used;
    for (const CalibrationSample& s : samples) {
        if (!didWork(s.work)) continue;
        const double weight = opt.relative ? 1.0 / std::max(s.minMs, opt.floorMs) : 1.0;
        std::vector<double> row;
        for (Feature f : features) row.push_back(weight * featureValue(s.work, f));
        a.push_back(std::move(row));
        b.push_back(weight * s.minMs);
        measured.push_back(s.minMs);
        used.push_back(&s);
    }
    PassModel m;
    m.samples = int(used.size());
    if (used.empty()) return m;
    const std::vector<double> x = nnls(a, b);
    for (std::size_t j = 0; j < features.size(); ++j) m.terms.push_back({features[j], x[j]});
    std::vector<double> predicted;
    for (const CalibrationSample* s : used) predicted.push_back(modelPass(m, s->work));
    m.r2 = rSquared(measured, predicted);
    return m;
}

CostProfile fitProfile(const std::vector<CalibrationSample>& samples, const FitOptions& opt) {
    CostProfile p;
    p.fittedOn = "pass minimum";
    for (PassKind k : kPassKinds) {
        std::vector<CalibrationSample> ofKind;
        std::copy_if(samples.begin(), samples.end(), std::back_inserter(ofKind),
                     [k](const CalibrationSample& s) { return s.kind == k; });
        p.pass(k) = fitPass(defaultFeatures(k), ofKind, opt);
    }
    for (const CalibrationSample& s : samples)
        p.residuals.push_back({s.preset, s.pass, s.minMs, s.medianMs, modelPass(p.pass(s.kind), s.work)});
    return p;
}

namespace {
// The frame's work of `kind` summed over its passes, per feature.
double frameFeature(const FrameWork& w, PassKind kind, Feature f) {
    switch (kind) {
        case PassKind::Cascade: {
            double sum = 0.0;
            for (const PassWork& c : w.cascades) sum += featureValue(c, f);
            return sum;
        }
        case PassKind::Main: return featureValue(w.main, f);
        case PassKind::Filter: return featureValue(w.filter, f);
        case PassKind::DepthBounds: return featureValue(w.depthBounds, f);
    }
    return 0.0;
}

// The frame's modelled time of `kind`, summed over its passes: the model is linear in the
// features, and a pass that did no work has none (not even the intercept).
double kindModelMs(const CostProfile& p, const FrameWork& w, PassKind kind) {
    double ms = 0.0;
    for (const Term& t : p.pass(kind).terms) ms += t.msPerUnit * frameFeature(w, kind, t.feature);
    return ms;
}
}  // namespace

bool fittedOnOwnTimers(PassKind k) { return k == PassKind::DepthBounds; }

namespace {
std::vector<CalibrationSample> samplesOfKind(const std::vector<CalibrationSample>& samples, PassKind k) {
    std::vector<CalibrationSample> out;
    std::copy_if(samples.begin(), samples.end(), std::back_inserter(out),
                 [k](const CalibrationSample& s) { return s.kind == k; });
    return out;
}
}  // namespace

CostProfile fitProfileOnFrames(const std::vector<CalibrationFrame>& frames,
                               const std::vector<CalibrationSample>& passes, const FitOptions& opt) {
    CostProfile p;
    p.fittedOn = "frame minimum";
    std::vector<std::pair<PassKind, Feature>> columns;
    for (PassKind k : kPassKinds) {
        if (fittedOnOwnTimers(k)) p.pass(k) = fitPass(defaultFeatures(k), samplesOfKind(passes, k), opt);
        else
            for (Feature f : defaultFeatures(k)) columns.emplace_back(k, f);
    }
    // What the jointly fitted kinds must explain: the frame less the own-timer kinds' model.
    const auto ownTimersMs = [&p](const FrameWork& w) {
        double ms = 0.0;
        for (PassKind k : kPassKinds)
            if (fittedOnOwnTimers(k)) ms += kindModelMs(p, w, k);
        return ms;
    };
    Matrix a;
    std::vector<double> b;
    for (const CalibrationFrame& fr : frames) {
        const double weight = opt.relative ? 1.0 / std::max(fr.minMs, opt.floorMs) : 1.0;
        std::vector<double> row;
        for (const auto& [k, f] : columns) row.push_back(weight * frameFeature(fr.work, k, f));
        a.push_back(std::move(row));
        b.push_back(weight * std::max(fr.minMs - ownTimersMs(fr.work), 0.0));
    }
    const std::vector<double> x = frames.empty() ? std::vector<double>(columns.size(), 0.0) : nnls(a, b);
    for (std::size_t j = 0; j < columns.size(); ++j) {
        const auto& [k, f] = columns[j];
        p.pass(k).terms.push_back({f, x[j]});
    }
    std::vector<double> measured, modelled;
    for (const CalibrationFrame& fr : frames) {
        measured.push_back(fr.minMs);
        modelled.push_back(modelFrame(p, fr.work).totalMs);
        p.residuals.push_back({fr.preset, "frame", fr.minMs, fr.medianMs, modelled.back()});
    }
    p.frameR2 = rSquared(measured, modelled);
    for (PassKind k : kPassKinds) {
        if (fittedOnOwnTimers(k)) continue;  // fitPass set its samples and R²
        std::vector<double> m, pred;
        for (const CalibrationSample& s : passes) {
            if (s.kind != k || !didWork(s.work)) continue;
            m.push_back(s.minMs);
            pred.push_back(modelPass(p.pass(k), s.work));
        }
        p.pass(k).samples = int(m.size());
        p.pass(k).r2 = rSquared(m, pred);
        if (m.empty()) p.pass(k).terms.clear();  // never seen: no evidence for any coefficient
    }
    for (const CalibrationSample& s : passes)
        p.residuals.push_back({s.preset, s.pass, s.minMs, s.medianMs, modelPass(p.pass(s.kind), s.work)});
    return p;
}

CostProfile refitOnOwnTimers(CostProfile base, PassKind k, const std::vector<CalibrationSample>& samples,
                             const std::string& calibrated, const FitOptions& opt) {
    if (!fittedOnOwnTimers(k))
        throw std::invalid_argument(std::string("the ") + passKindName(k) +
                                    " pass is fitted jointly on frame totals; calibrate the whole profile");
    const std::vector<CalibrationSample> ofKind = samplesOfKind(samples, k);
    base.pass(k) = fitPass(defaultFeatures(k), ofKind, opt);
    base.pass(k).calibrated = calibrated;
    std::erase_if(base.residuals, [k](const Residual& r) { return r.pass == passKindName(k); });
    for (const CalibrationSample& s : ofKind)
        base.residuals.push_back({s.preset, s.pass, s.minMs, s.medianMs, modelPass(base.pass(k), s.work)});
    return base;
}

}  // namespace st::metrics
