#include "app/cli/check_command.h"

#include "app/cost_profile_file.h"
#include "app/version.h"

#include "check/annotations.h"
#include "check/check_run.h"
#include "check/golden_store.h"
#include "check/html_report.h"
#include "check/junit_writer.h"
#include "check/results_json.h"
#include "check/suite_file.h"
#include "metrics/measure_session.h"
#include "metrics/metrics_json.h"
#include "renderer/context/egl_context.h"
#include "renderer/render/device.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_spec.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <tuple>

namespace st::app {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

// The frame and figures of one entry, by the code paths of `render` and `measure` (the same
// MeasureSession and metrics.json), at the suite's size.
check::Actual replay(const check::SuiteEntry& e, metrics::MeasureSession& session, const metrics::CostProfile& profile,
                     const std::string& renderer) {
    Settings s = loadPreset(e.preset);
    if (e.size) std::tie(s.output.width, s.output.height) = *e.size;
    const fs::path dir = folderOf(e.preset);
    Renderer& r = *session.entryFor(s, dir).renderer;
    r.render(s);
    check::Actual a;
    a.image = {r.width(), r.height(), r.readRgba8()};
    metrics::MeasureOptions mo;  // measure's defaults, as `shadowtune measure` runs them
    mo.costProfile = &profile;
    a.figures = metrics::toJson(session.measure(s, dir, mo), e.name);
    a.meta = {renderer, productVersion(), buildCommit(), sweep::settingsId(s), a.image.width, a.image.height};
    return a;
}

void printChanges(const check::PresetResult& r) {
    if (r.status == check::Status::Unchanged) return;
    std::printf("%s: %s -> %s\n", r.name.c_str(), check::statusName(r.status), r.goldenDir.c_str());
    for (const std::string& n : r.notes) std::printf("  %s\n", n.c_str());
    std::fflush(stdout);
}

// One entry's verdict; an entry that cannot be replayed or read is an ERROR, not the end of the run.
check::PresetResult checkOne(const CheckCommandOptions& opt, const check::SuiteEntry& e, metrics::MeasureSession& session,
                             const metrics::CostProfile& profile, const std::string& renderer, std::size_t index) {
    const auto t0 = Clock::now();
    check::PresetResult r;
    try {
        const check::Actual a = replay(e, session, profile, renderer);
        const fs::path dir = check::goldenDir(opt.golden, renderer, e.name);
        const std::optional<check::Golden> golden = check::readGolden(dir);
        r = opt.update ? check::updateVerdict(e, a, golden) : check::judge(e, a, golden);
        r.goldenDir = dir.string();
        if (opt.update && r.status != check::Status::Unchanged) check::writeGolden({dir, a.meta, a.image, a.figures});
        if (!opt.reportDir.empty())
            check::writePresetImages(opt.reportDir, index, r, a.image, golden ? &*golden : nullptr, e.image);
    } catch (const std::exception& ex) {
        r = {};
        r.name = e.name;
        r.preset = e.preset.string();
        r.note = e.note;
        r.status = check::Status::Error;
        r.message = ex.what();
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
}

void writeOutputs(const CheckCommandOptions& opt, const check::RunInfo& info, const std::vector<check::PresetResult>& results) {
    if (!opt.reportDir.empty()) check::writeReport(opt.reportDir, info, results);
    if (!opt.junit.empty()) {
        if (!opt.junit.parent_path().empty()) fs::create_directories(opt.junit.parent_path());
        writeTextAtomic(opt.junit, check::junitXml(opt.suite.stem().string(), results, opt.reportDir));
    }
    const char* gha = std::getenv("GITHUB_ACTIONS");
    if (gha && *gha)
        for (const std::string& line : check::githubAnnotations(results)) std::printf("%s\n", line.c_str());
}

}  // namespace

int runCheck(const CheckCommandOptions& opt) {
    std::vector<check::SuiteEntry> entries;
    try {
        entries = check::selectEntries(check::loadSuite(opt.suite).entries, opt.only);
    } catch (const check::SuiteError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
    if (entries.empty()) {
        std::fprintf(stderr, "error: --only '%s' matches no preset of %s\n", opt.only.c_str(), opt.suite.string().c_str());
        return 2;
    }
    const auto profile = loadCostProfileOrReport(fs::path());
    if (!profile) return 2;
    std::unique_ptr<HeadlessContext> ctx;
    try {
        ctx = HeadlessContext::create(false);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: no GL context: %s\n", e.what());
        return 2;
    }
    const std::string renderer = deviceRendererName();
    std::vector<check::PresetResult> results;
    {
        metrics::MeasureSession session;  // its GL objects go while the context is current
        for (std::size_t i = 0; i < entries.size(); ++i) {
            results.push_back(checkOne(opt, entries[i], session, *profile, renderer, i));
            const check::PresetResult& r = results.back();
            const std::string why = check::isFailure(r.status) ? ": " + r.message : "";
            std::fprintf(stderr, "[%zu/%zu] %s: %s (%.1f s)%s\n", i + 1, entries.size(), r.name.c_str(),
                         check::statusName(r.status), r.seconds, why.c_str());
            if (opt.update) printChanges(r);
        }
    }
    const check::RunInfo info{opt.suite.string(), opt.golden.string(), renderer, versionText(), opt.update};
    try {
        writeOutputs(opt, info, results);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
    const int code = check::exitCodeOf(results);
    std::size_t failures = 0;
    for (const check::PresetResult& r : results) failures += check::isFailure(r.status) ? 1 : 0;
    std::fprintf(stderr, "%zu of %zu presets failed%s\n", failures, results.size(),
                 opt.update ? " (--update: the others' goldens written where they changed)" : "");
    return code;
}

}  // namespace st::app
