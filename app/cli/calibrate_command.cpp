#include "app/cli/calibrate_command.h"

#include "app/cli/calibration_set.h"
#include "app/cost_profile_file.h"
#include "app/preset_dir.h"
#include "metrics/calibration.h"
#include "metrics/cost.h"
#include "metrics/cost_profile_json.h"
#include "metrics/model_error.h"
#include "renderer/context/egl_context.h"
#include "renderer/csm/cascade_plan.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/render/pass_work_json.h"
#include "renderer/render/scene_cache.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_spec.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <optional>
#include <string>
#include <thread>

namespace st::app {
namespace fs = std::filesystem;
namespace {

// "AMD EPYC 7B13, 2 cores": the CPU runs llvmpipe, so it is the machine a profile is for.
std::string machineText() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const std::size_t colon = line.find(':');
        if (colon != std::string::npos) model = line.substr(line.find_first_not_of(' ', colon + 1));
        break;
    }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
    return text;
}

// Frame totals modelled and measured (minimum and median over the frames), one per point.
struct FrameComparison {
    std::vector<double> model, minMs, medianMs;

    void add(double modelMs, const metrics::TimedFrames& t) {
        const std::vector<double> totals = metrics::frameTotalsMs(t);
        model.push_back(modelMs);
        minMs.push_back(metrics::minimum(totals));
        medianMs.push_back(metrics::median(totals));
    }
    void print(const char* what) const {
        std::printf("%s: %zu frames; median |model - measured| / measured %s against the minimum, %s against the "
                    "median; Spearman %.3f against the minimum, %.3f against the median\n",
                    what, model.size(), percent(metrics::medianRelativeError(model, minMs)).c_str(),
                    percent(metrics::medianRelativeError(model, medianMs)).c_str(), metrics::spearman(model, minMs),
                    metrics::spearman(model, medianMs));
    }
};

void printPointLine(const std::string& counter, const std::string& name, const Settings& s,
                    const metrics::TimedFrames& t, const double* modelMs) {
    const std::vector<double> totals = metrics::frameTotalsMs(t);
    std::fprintf(stderr, "%s %s %dx%d: frame %.1f ms min, %.1f ms median", counter.c_str(), name.c_str(),
                 s.output.width, s.output.height, metrics::minimum(totals), metrics::median(totals));
    if (modelMs) std::fprintf(stderr, ", model %.1f ms", *modelMs);
    if (!t.workStable) std::fprintf(stderr, " (warning: counted work differed between frames)");
    std::fprintf(stderr, "\n");
}

// --samples: one line per timed point, written as the points are timed (a run stopped halfway
// keeps what it timed).
class SampleLog {
public:
    explicit SampleLog(const fs::path& file) {
        if (file.empty()) return;
        out_.open(file);
        if (!out_) throw std::runtime_error("cannot write " + file.string());
    }
    void add(const std::string& sweep, const std::string& name, const Settings& s, const metrics::TimedFrames& t) {
        if (!out_.is_open()) return;
        const std::vector<double> totals = metrics::frameTotalsMs(t);
        nlohmann::ordered_json j;
        j["sweep"] = sweep;
        j["name"] = name;
        j["size"] = {s.output.width, s.output.height};
        j["minMs"] = metrics::minimum(totals);
        j["medianMs"] = metrics::median(totals);
        j["framesMs"] = totals;
        j["work"] = frameWorkJson(t.work);
        out_ << j.dump() << "\n" << std::flush;
    }

private:
    std::ofstream out_;
};

// Another pass's frames of the same point joined to the first's: the machine's speed drifts over
// minutes, so the minimum over passes spread in time is steadier than over frames in a row.
void addPass(metrics::TimedFrames& into, metrics::TimedFrames&& more) {
    into.workStable = into.workStable && more.workStable && more.work == into.work;
    for (FrameStats& f : more.frames) into.frames.push_back(std::move(f));
}

std::string passCounter(const char* what, int pass, int passes, std::size_t i, std::size_t n) {
    std::string out = what;
    if (passes > 1) out += " pass " + std::to_string(pass + 1) + "/" + std::to_string(passes);
    return out + " [" + std::to_string(i + 1) + "/" + std::to_string(n) + "]";
}

void printProfile(const metrics::CostProfile& p) {
    for (metrics::PassKind k : metrics::kPassKinds) {
        const metrics::PassModel& m = p.pass(k);
        std::printf("  %-11s %3d samples, R² %.3f against its own timers:", metrics::passKindName(k), m.samples, m.r2);
        for (const metrics::Term& t : m.terms) std::printf(" %s %.4g", metrics::featureName(t.feature), t.msPerUnit);
        std::printf("\n");
    }
}

// Names the renderer by its first word ("llvmpipe", "NVIDIA", ...): a profile of another one
// models another machine.
bool sameRenderer(const std::string& a, const std::string& b) {
    return a.substr(0, a.find(' ')) == b.substr(0, b.find(' '));
}

void warnIfOtherRenderer(const metrics::CostProfile& p, const HeadlessContext& ctx) {
    if (!sameRenderer(p.renderer, ctx.rendererName()))
        std::fprintf(stderr, "warning: the profile is for \"%s\", this is \"%s\"\n", p.renderer.c_str(),
                     ctx.rendererName().c_str());
}

// The points' frames, each joined over opt.passes passes (points that failed are left out and
// named in `failed`), logged to --samples.
struct TimedPoints {
    std::vector<std::string> names;
    std::vector<metrics::TimedFrames> frames;
    std::vector<std::string> failed;
};

TimedPoints timePoints(const CalibrateOptions& opt, const std::vector<CalibrationPoint>& points) {
    SceneCache<> scenes(true);  // one scene at a time: see SceneCache(bool)
    SampleLog log(opt.samples);
    std::vector<std::optional<metrics::TimedFrames>> byPoint(points.size());
    std::vector<bool> broken(points.size(), false);
    TimedPoints out;
    for (int pass = 0; pass < opt.passes; ++pass) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            const CalibrationPoint& p = points[i];
            if (broken[i]) continue;
            const std::string counter = passCounter("calibrate", pass, opt.passes, i, points.size());
            try {
                metrics::TimedFrames t = metrics::timeFrames(scenes.rendererFor(p.settings, p.presetDir), p.settings, opt.frames);
                printPointLine(counter, p.name, p.settings, t, nullptr);
                if (byPoint[i]) addPass(*byPoint[i], std::move(t));
                else byPoint[i] = std::move(t);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "%s %s: error: %s\n", counter.c_str(), p.name.c_str(), e.what());
                out.failed.push_back(p.name);
                broken[i] = true;
                byPoint[i].reset();
            }
        }
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!byPoint[i]) continue;
        log.add("", points[i].name, points[i].settings, *byPoint[i]);
        out.names.push_back(points[i].name);
        out.frames.push_back(std::move(*byPoint[i]));
    }
    return out;
}

std::vector<metrics::CalibrationSample> samplesOf(const TimedPoints& t) {
    std::vector<metrics::CalibrationSample> samples;
    for (std::size_t i = 0; i < t.frames.size(); ++i)
        for (metrics::CalibrationSample& s : metrics::passSamples(t.names[i], t.frames[i])) samples.push_back(std::move(s));
    return samples;
}

int reportFailed(const TimedPoints& t, std::size_t points) {
    if (t.failed.empty()) return 0;
    std::fprintf(stderr, "error: %zu of %zu calibration points failed (first: %s); the profile was fitted without them\n",
                 t.failed.size(), points, t.failed.front().c_str());
    return 1;
}

int calibrate(const CalibrateOptions& opt, const HeadlessContext& ctx) {
    const fs::path presetDir = opt.presetDir.empty() ? defaultPresetDir() : opt.presetDir;
    const std::vector<CalibrationPoint> points = calibrationSet(presetDir, opt.size, opt.sweeps);
    const TimedPoints timed = timePoints(opt, points);
    std::vector<metrics::CalibrationFrame> frames;
    for (std::size_t i = 0; i < timed.frames.size(); ++i) {
        const std::vector<double> totals = metrics::frameTotalsMs(timed.frames[i]);
        frames.push_back({timed.names[i], timed.frames[i].work, metrics::minimum(totals), metrics::median(totals)});
    }
    metrics::CostProfile profile = metrics::fitProfileOnFrames(frames, samplesOf(timed));
    profile.renderer = ctx.rendererName();
    profile.machine = machineText();
    profile.date = utcNow();
    profile.frames = opt.frames;
    metrics::saveCostProfileAtomic(profile, opt.out);
    std::printf("cost profile for %s (%s) in %s\n", profile.renderer.c_str(), profile.machine.c_str(),
                opt.out.string().c_str());
    std::printf("  frame totals: R² %.3f (%s)\n", profile.frameR2, profile.fittedOn.c_str());
    printProfile(profile);
    FrameComparison fit;
    for (const metrics::TimedFrames& t : timed.frames) fit.add(metrics::modelFrame(profile, t.work).totalMs, t);
    fit.print("calibration frames (in-sample)");
    return reportFailed(timed, points.size());
}

// --refit KIND: only the calibration points that run that pass are timed, and only its
// coefficients change; the other kinds keep --profile's (metrics::refitOnOwnTimers).
int refit(const CalibrateOptions& opt, const HeadlessContext& ctx) {
    const std::optional<metrics::PassKind> named = metrics::passKindFromName(opt.refit);
    if (!named || !metrics::fittedOnOwnTimers(*named))
        throw std::runtime_error("--refit: " + opt.refit + " is not a pass kind fitted on its own timers (depthBounds)");
    const metrics::PassKind kind = *named;
    const metrics::CostProfile base = loadCostProfileOption(opt.profile);
    warnIfOtherRenderer(base, ctx);
    const fs::path presetDir = opt.presetDir.empty() ? defaultPresetDir() : opt.presetDir;
    std::vector<CalibrationPoint> points = calibrationSet(presetDir, opt.size, opt.sweeps);
    // Depth bounds, the one kind fitted alone, runs where the settings need sample bounds.
    std::erase_if(points, [](const CalibrationPoint& p) { return !csm::needsSampleBounds(p.settings.cascades); });
    if (points.empty()) throw std::runtime_error("no calibration point runs the " + opt.refit + " pass");
    const TimedPoints timed = timePoints(opt, points);
    const std::vector<metrics::CalibrationSample> samples = samplesOf(timed);
    const metrics::CostProfile profile =
        metrics::refitOnOwnTimers(base, kind, samples, machineText() + ", " + utcNow());
    metrics::saveCostProfileAtomic(profile, opt.out);
    std::printf("%s refitted on %d samples (R² %.3f against its timers), the other kinds kept from %s, in %s\n",
                opt.refit.c_str(), profile.pass(kind).samples, profile.pass(kind).r2, metrics::profileName(base).c_str(),
                opt.out.string().c_str());
    printProfile(profile);
    std::printf("pass\tpreset\tmeasured min ms\tmodel before ms\tmodel now ms\n");
    for (const metrics::CalibrationSample& s : samples) {
        if (s.kind != kind) continue;
        std::printf("%s\t%s\t%.2f\t%.2f\t%.2f\n", s.pass.c_str(), s.preset.c_str(), s.minMs,
                    metrics::modelPass(base.pass(kind), s.work), metrics::modelPass(profile.pass(kind), s.work));
    }
    return reportFailed(timed, points.size());
}

int check(const CalibrateOptions& opt, const HeadlessContext& ctx) {
    const metrics::CostProfile profile = loadCostProfileOption(opt.profile);
    warnIfOtherRenderer(profile, ctx);
    SceneCache<> scenes(true);  // one scene at a time: see SceneCache(bool)
    FrameComparison all;
    SampleLog log(opt.samples);
    int unreadable = 0;
    struct Checked {
        std::string sweep, label;
        Settings settings;
        fs::path presetDir;
        std::optional<metrics::TimedFrames> timed;
    };
    std::vector<Checked> checked;
    for (const fs::path& file : opt.check) {
        sweep::SweepSpec spec;
        try {
            spec = sweep::loadSweep(file);
            for (const std::string& a : spec.adapted) std::fprintf(stderr, "note: %s: reference %s\n", spec.name.c_str(), a.c_str());
        } catch (const SettingsError& e) {  // the other sweeps still give figures
            for (const std::string& m : e.messages()) std::fprintf(stderr, "error: %s\n", m.c_str());
            ++unreadable;
            continue;
        }
        const std::vector<sweep::Point> points = expandPoints(spec);
        for (std::size_t i = 0; i < points.size(); i += std::size_t(opt.every)) {
            Settings s = points[i].settings;
            if (opt.size) std::tie(s.output.width, s.output.height) = *opt.size;
            checked.push_back({spec.name, points[i].label, s, spec.presetDir, std::nullopt});
        }
    }
    for (int pass = 0; pass < opt.passes; ++pass) {
        for (std::size_t i = 0; i < checked.size(); ++i) {
            Checked& c = checked[i];
            metrics::TimedFrames t = metrics::timeFrames(scenes.rendererFor(c.settings, c.presetDir), c.settings, opt.frames);
            const double model = metrics::modelFrame(profile, t.work).totalMs;
            printPointLine(passCounter(("check " + c.sweep).c_str(), pass, opt.passes, i, checked.size()), c.label,
                           c.settings, t, &model);
            if (c.timed) addPass(*c.timed, std::move(t));
            else c.timed = std::move(t);
        }
    }
    for (const Checked& c : checked) {
        all.add(metrics::modelFrame(profile, c.timed->work).totalMs, *c.timed);
        log.add(c.sweep, c.label, c.settings, *c.timed);
        std::printf("%s\t%s\t%.3f\t%.3f\t%.3f\n", c.sweep.c_str(), c.label.c_str(), all.model.back(), all.minMs.back(),
                    all.medianMs.back());
    }
    all.print(("sweep points against " + profile.renderer).c_str());
    if (unreadable)
        std::fprintf(stderr, "error: %d sweep files could not be read (above); their points are not in the figures\n",
                     unreadable);
    return unreadable ? 1 : 0;
}

}  // namespace

int runCalibrate(const CalibrateOptions& opt) {
    try {
        auto ctx = HeadlessContext::create(opt.debugContext);
        if (opt.debugContext) gpu::enableDebugOutput();
        const int before = gpu::seriousDebugMessageCount();
        const int code = !opt.check.empty() ? check(opt, *ctx) : !opt.refit.empty() ? refit(opt, *ctx) : calibrate(opt, *ctx);
        if (gpu::seriousDebugMessageCount() != before) {
            std::fprintf(stderr, "error: GL debug output reported errors\n");
            return 2;
        }
        return code;
    } catch (const SettingsError& e) {
        for (const std::string& m : e.messages()) std::fprintf(stderr, "error: %s\n", m.c_str());
        return 1;
    } catch (const metrics::CostProfileError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}

}  // namespace st::app
