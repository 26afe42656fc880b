#include "app/cli/tune_command.h"

#include "app/cost_profile_file.h"
#include "app/cli/interrupt_watch.h"
#include "app/cli/tune_engine_proof.h"
#include "metrics/cost_profile_json.h"
#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/render/device.h"
#include "renderer/settings/settings_json.h"
#include "tune/tune_run.h"

#include <unistd.h>

#include <optional>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace st::app {
namespace {

// Progress on stderr: on a terminal, the evaluation lines overwrite each other (a bar with the best
// so far); elsewhere (CI logs), every line.
class ProgressLine {
public:
    ProgressLine() : tty_(isatty(fileno(stderr)) != 0) {}
    ~ProgressLine() { finish(); }
    void operator()(const std::string& line) {
        const bool evaluation = line.rfind("tune [", 0) == 0;
        if (tty_ && evaluation) {
            std::fprintf(stderr, "\r%-*.*s", kWidth, kWidth, line.c_str());
            open_ = true;
        } else {
            finish();
            std::fprintf(stderr, "%s\n", line.c_str());
        }
        std::fflush(stderr);
    }
    void finish() {
        if (open_) std::fprintf(stderr, "\n");
        open_ = false;
    }

private:
    static constexpr int kWidth = 118;
    bool tty_ = false, open_ = false;
};

// The engine's own figures, or why it could not give them: the tune itself stands either way.
void reportProof(const EngineProof& p) {
    if (!p.ran) return;
    if (p.error.empty()) std::printf("%s\n", p.line.c_str());
    else std::fprintf(stderr, "warning: the tune is not proven in the engine: %s\n", p.error.c_str());
}

}  // namespace

int runTuneCommand(const TuneCommandOptions& opt) {
    try {
        const metrics::CostProfile profile = loadCostProfileOption(opt.costProfile);
        auto ctx = HeadlessContext::create(opt.debugGl);
        if (opt.debugGl) gpu::enableDebugOutput();
        const int before = gpu::seriousDebugMessageCount();
        tune::TuneOptions to;
        to.preset = opt.preset;
        to.outDir = opt.outDir;
        to.budgetMs = opt.budgetMs;
        to.budgetMiB = opt.budgetMiB;
        to.budgetFrom = opt.budgetFrom;
        to.compareWith = opt.compareWith;
        to.rendererPerView = !opt.sharedRenderer;
        to.size = opt.size;
        to.objective = opt.objective;
        to.views = opt.views;
        to.holdOutEvery = opt.holdOutEvery;
        to.seed = opt.seed;
        to.evaluations = opt.evaluations;
        to.constraints = !opt.noConstraints;
        to.front = opt.front;
        to.engine = opt.engine;
        to.stopAfter = opt.stopAfter;
        to.shard = {opt.shardIndex, opt.shardCount};
        to.shardWaitSeconds = opt.shardWaitSeconds;
        to.profile = &profile;
        to.machine = deviceRendererName() + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
        ProgressLine progress;
        to.progress = [&](const std::string& line) { progress(line); };
        std::optional<InterruptWatch> ctrlC(std::in_place);  // first Ctrl-C: finish the evaluation under way
        to.stopRequested = [] { return InterruptWatch::requested(); };
        const tune::TuneOutcome out = tune::runTune(to);
        ctrlC.reset();
        progress.finish();
        if (gpu::seriousDebugMessageCount() != before) {
            std::fprintf(stderr, "error: GL debug output reported errors during the tune\n");
            return 2;
        }
        if (out.infeasible) {
            std::fprintf(stderr, "error: %s\n", out.message.c_str());
            return 1;
        }
        std::printf("%s\n", out.message.c_str());
        if (out.stopped) return InterruptWatch::requested() ? 130 : 0;
        ctx.reset();  // engine-check makes its own context
        if (opt.shardIndex == 1) reportProof(proveInEngine(opt));
        return 0;
    } catch (const SettingsError& e) {
        for (const std::string& m : e.messages()) std::fprintf(stderr, "error: %s\n", m.c_str());
        return 1;
    } catch (const metrics::CostProfileError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    } catch (const std::runtime_error& e) {  // a folder of another tune, an unwritable folder
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}

}  // namespace st::app
