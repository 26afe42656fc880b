#include "app/cli/sweep_command.h"

#include "app/cost_profile_file.h"
#include "app/cli/interrupt_watch.h"
#include "metrics/cost_profile_json.h"
#include "app/cli/sweep_progress.h"
#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/render/device.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_run.h"

#include <cstdio>
#include <stdexcept>
#include <thread>

namespace st::app {
namespace fs = std::filesystem;
namespace {

std::string machineText() {
    const std::string renderer = deviceRendererName();
    return (renderer.empty() ? "unknown GL renderer" : renderer) + ", " +
           std::to_string(std::thread::hardware_concurrency()) + " cores";
}

// "k/n" with 1 <= k <= n; throws std::invalid_argument otherwise.
std::pair<int, int> parseShard(const std::string& text) {
    int k = 0, n = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 1 || k > n)
        throw std::invalid_argument("--shard: expected k/n with 1 <= k <= n (e.g. 2/4), got \"" + text + "\"");
    return {k, n};
}

int runOnce(const sweep::SweepSpec& spec, sweep::RunOptions ro, bool debugGl) {
    auto ctx = HeadlessContext::create(debugGl);
    if (debugGl) gpu::enableDebugOutput();
    ro.machine = machineText();
    InterruptWatch ctrlC;  // first Ctrl-C: finish the current point, then stop with everything written
    ro.stopRequested = [] { return InterruptWatch::requested(); };
    SweepProgress progress(stderr);
    ro.progress = [&](const sweep::Progress& p) { progress(p); };
    const int before = gpu::seriousDebugMessageCount();
    const sweep::RunOutcome out = sweep::runSweep(spec, ro);
    progress.finish();
    std::printf("sweep %s: %zu of %zu points measured, %zu resumed; front of %zu points in %s\n", spec.name.c_str(),
                out.measured, out.total, out.resumed, out.front.size(), (ro.outDir / "front.json").string().c_str());
    if (gpu::seriousDebugMessageCount() != before) {
        std::fprintf(stderr, "error: GL debug output reported errors during the sweep\n");
        return 2;
    }
    if (out.stopped) {
        std::printf("stopped after %zu new points; run the same command again to resume\n", out.measured);
        return InterruptWatch::requested() ? 130 : 0;
    }
    return 0;
}

}  // namespace

int runSweepCommand(const SweepCommandOptions& opt) {
    try {
        sweep::ReportOptions report{opt.error, opt.cost};
        sweep::errorFigure(opt.error);  // refuse a bad --error or --cost before any work
        sweep::costFigure(opt.cost);
        if (!opt.merge.empty()) {
            const std::size_t n = sweep::mergeSweeps(opt.merge, opt.outDir, report);
            std::printf("merged %zu shard folders: %zu points in %s\n", opt.merge.size(), n, opt.outDir.string().c_str());
            return 0;
        }
        if (opt.sweepFile.empty()) throw std::invalid_argument("give a sweep file, or --merge DIR... to join shards");
        const sweep::SweepSpec spec = sweep::loadSweep(opt.sweepFile);
        for (const std::string& a : spec.adapted) std::fprintf(stderr, "note: reference %s\n", a.c_str());
        sweep::RunOptions ro;
        ro.outDir = opt.outDir;
        if (!opt.shard.empty()) std::tie(ro.shardIndex, ro.shardCount) = parseShard(opt.shard);
        ro.stopAfter = opt.stopAfter;
        ro.costFrames = opt.costFrames;
        ro.report = report;
        const metrics::CostProfile profile = loadCostProfileOption(opt.costProfile);
        ro.costProfile = &profile;
        return runOnce(spec, ro, opt.debugGl);
    } catch (const SettingsError& e) {
        for (const std::string& m : e.messages()) std::fprintf(stderr, "error: %s\n", m.c_str());
        return 1;
    } catch (const metrics::CostProfileError& e) {  // bad input, like a bad sweep file
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}

}  // namespace st::app
