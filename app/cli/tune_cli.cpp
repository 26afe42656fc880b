// `shadowtune tune`: command-line options of the tuner.
#include "app/cli/commands.h"
#include "app/cli/number_checks.h"
#include "app/cli/size_option.h"
#include "app/cli/tune_command.h"
#include "sweep/sweep_results.h"

#include <cstdio>
#include <memory>
#include <regex>

namespace st::app {
namespace {

// "k/n" with 1 <= k <= n <= 1000, as a Slurm array's task id over its count reads.
bool parseShard(const std::string& text, int& k, int& n) {
    std::smatch m;
    static const std::regex form(R"(\s*(\d{1,4})\s*/\s*(\d{1,4})\s*)");
    if (!std::regex_match(text, m, form)) return false;
    k = std::stoi(m[1]);
    n = std::stoi(m[2]);
    return k >= 1 && n >= 1 && k <= n && n <= 1000;
}

}  // namespace

void addTuneCommand(CLI::App& cli, int& exitCode) {
    auto opt = std::make_shared<TuneCommandOptions>();
    auto budgetMs = std::make_shared<double>(0.0);
    auto budgetMiB = std::make_shared<double>(0.0);
    auto size = std::make_shared<std::string>();
    auto shard = std::make_shared<std::string>();
    auto constraints = std::make_shared<std::string>("artifacts");
    auto engine = std::make_shared<std::string>();
    CLI::App* cmd = cli.add_subcommand(
        "tune", "Find the best settings for a preset's scene within a cost budget, by search, and explain them");
    cmd->add_option("preset", opt->preset, "Preset to tune (its scene, camera, light and size stay)")->required();
    cmd->add_option("--out", opt->outDir, "Output folder (tuned.json, front/, explain.md); rerun to resume")->required();
    CLI::Option* ms = cmd->add_option("--budget-ms", *budgetMs, "Modelled frame cost at most this (ms)")
                          ->check(positiveNumber());
    CLI::Option* mib = cmd->add_option("--budget-mib", *budgetMiB, "Shadow and filter map memory at most this (MiB)")
                           ->check(positiveNumber());
    cmd->add_option("--budget-from", opt->budgetFrom,
                    "Reference presets: their method on this scene and views sets the budget (the cheapest's cost and "
                    "memory, unless --budget-ms/--budget-mib are given)")
        ->expected(1, -1)
        ->check(CLI::ExistingFile);
    cmd->add_option("--compare-with", opt->compareWith,
                    "Presets whose method is measured on the same views and drawn on the front, without setting the "
                    "budget (the editor's A)")
        ->expected(1, -1)
        ->check(CLI::ExistingFile);
    cmd->add_option("--size", *size, "Tune at this output size, WxH, instead of the preset's");
    cmd->add_option("--objective", opt->objective,
                    "Error figure to minimise; the soft truth's artifact classes may not get worse than the input's")
        ->check(CLI::IsMember(sweep::errorChoices()))
        ->capture_default_str();
    cmd->add_option("--constraints", *constraints,
                    "artifacts: the soft truth's artifact classes (and a path's flicker) may not get worse than the "
                    "input's; none: the objective alone, as a sweep's front ranks points")
        ->check(CLI::IsMember({"artifacts", "none"}))
        ->capture_default_str();
    cmd->add_option("--engine", *engine,
                    "Tune for this engine: its own knobs only (" + xport::knobEngineList() +
                    "); writes ENGINE.json (its knobs) and its paste-ready text beside tuned.json")
        ->check(CLI::Validator(
            [](std::string& name) {  // every engine with a knob table: a new table needs no line here
                return xport::parseKnobEngine(name) ? std::string() : "'" + name + "' is not one of " + xport::knobEngineList();
            },
            "ENGINE"));
    cmd->add_flag("--no-engine-check", opt->noEngineCheck,
                  "With --engine " + xport::loopEngineList() + ": skip running the tuned knobs and the defaults in the real engine "
                  "on the tune's views (summary.json's engine object, explain.md's table)");
    cmd->add_flag("--front", opt->front,
                  "Keep a quarter of the evaluations for a descent to cheaper settings from the tuned point: front/ "
                  "then charts cost against error from the cheapest to the budget (docs/tuning.md#front)");
    cmd->add_option("--views", opt->views, "Views: the preset's camera, then viewpoints around it")
        ->check(numberIn(1, 16))
        ->capture_default_str();
    cmd->add_option("--hold-out-every", opt->holdOutEvery,
                    "Every k-th view after the first is held out and only scores the result (0: none)")
        ->check(numberIn(0, 16))
        ->capture_default_str();
    cmd->add_option("--seed", opt->seed, "Seed of the search's order and restarts: the same seed gives the same tuned.json")
        ->capture_default_str();
    cmd->add_option("--evaluations", opt->evaluations, "Evaluations the search may make")
        ->check(numberIn(1, 100000))
        ->capture_default_str();
    cmd->add_option("--stop-after", opt->stopAfter, "Make at most N new evaluations, then stop as Ctrl-C would")
        ->check(nonNegativeNumber());
    cmd->add_option("--profile", opt->costProfile,
                    "Cost profile of the modelled cost (default: the shipped llvmpipe profile)");
    cmd->add_option("--shard", *shard,
                    "k/n: this process is shard k of n tunes of the same command on one shared --out folder; each "
                    "measures its share of every round, and shard 1 writes the results (docs/tuning.md#shards)");
    cmd->add_option("--shard-wait", opt->shardWaitSeconds,
                    "Seconds to wait for another shard's measurement before measuring it here")
        ->check(positiveNumber())
        ->capture_default_str();
    cmd->add_flag("--shared-renderer", opt->sharedRenderer,
                  "Measure every view with one renderer, redrawing every map at each change of view (the "
                  "baseline scripts/bench_tune.sh compares with; the result is the same)");
    cmd->add_flag("--debug-gl", opt->debugGl, "Debug GL context; a medium/high KHR_debug message fails the tune");
    cmd->callback([opt, budgetMs, budgetMiB, size, shard, constraints, engine, ms, mib, &exitCode] {
        opt->noConstraints = *constraints == "none";
        if (!engine->empty()) opt->engine = xport::parseKnobEngine(*engine);
        if (!shard->empty() && !parseShard(*shard, opt->shardIndex, opt->shardCount)) {
            std::fprintf(stderr, "error: --shard: expected k/n with 1 <= k <= n <= 1000, got '%s'\n", shard->c_str());
            exitCode = 2;
            return;
        }
        if (!size->empty()) {
            opt->size = parseSize(*size);
            if (!opt->size) {
                std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", size->c_str());
                exitCode = 2;
                return;
            }
        }
        if (*ms) opt->budgetMs = *budgetMs;
        if (*mib) opt->budgetMiB = *budgetMiB;
        exitCode = runTuneCommand(*opt);
    });
}

}  // namespace st::app
