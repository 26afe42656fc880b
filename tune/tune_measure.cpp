// Measurements: the journal first, then another shard's, then a new one; a sharded round's plan.
#include "tune/tuner.h"

#include "metrics/cost.h"
#include "metrics/figure_table.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"
#include "tune/tune_engine.h"
#include "tune/tune_eval.h"
#include "tune/tune_explain.h"
#include "tune/tune_holdout.h"
#include "tune/tune_journal.h"
#include "tune/tune_views.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

namespace st::tune::detail {

Evaluation Tuner::measured(const Settings& s, const std::string& views, bool waitForOwner) {
    if (std::optional<Evaluation> e = journal_->find(s, views)) return *e;
    if (opt_.shard.sharded()) {
        if (std::optional<Evaluation> e = fromAnotherShard(s, views, waitForOwner)) return *e;
    }
    const auto t0 = std::chrono::steady_clock::now();
    Evaluation e = views == "screen" ? screener_->measure(s, false) : evaluator_->measure(s, views == "held-out");
    (views == "screen" ? screenMs_ : evalMs_)
        .push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    journal_->add(s, views, e);
    ++made_;
    return e;
}

std::optional<Evaluation> Tuner::fromAnotherShard(const Settings& s, const std::string& views, bool wait) {
    journal_->refresh();
    if (std::optional<Evaluation> e = journal_->find(s, views)) return ++fromShards_, e;
    const int owner = ownerOf(s, views, opt_.shard.count);
    if (!wait || owner == opt_.shard.index || othersSilent_) return std::nullopt;
    const auto t0 = std::chrono::steady_clock::now();
    const auto deadline = t0 + std::chrono::duration<double>(opt_.shardWaitSeconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (opt_.stopRequested && opt_.stopRequested()) throw StoppedWhileWaiting{};
        if (!measureAhead(s)) std::this_thread::sleep_for(std::chrono::milliseconds(50));
        journal_->refresh();
        if (std::optional<Evaluation> e = journal_->find(s, views)) return ++fromShards_, e;
    }
    othersSilent_ = true;
    say("warning: shard " + std::to_string(owner) + "/" + std::to_string(opt_.shard.count) + " wrote nothing in " +
        fixed(opt_.shardWaitSeconds, 0) + " s; this shard measures every point from now on");
    return std::nullopt;
}

void Tuner::plan(const Settings& from, std::vector<Settings> next) {
    planFrom_ = from;
    plan_ = std::move(next);
}

bool Tuner::owned(const Settings& s, const std::string& views) const {
    return ownerOf(s, views, opt_.shard.count) == opt_.shard.index && !journal_->find(s, views);
}

bool Tuner::measureAhead(const Settings& waitedFor) {
    std::size_t i = 0;
    while (i < plan_.size() && !(plan_[i] == waitedFor) && !(screenSize(plan_[i]) == waitedFor)) ++i;
    const std::optional<Evaluation> from = journal_->find(planFrom_, "tuned");
    if (i == plan_.size() || !from) return false;
    const Evaluation at = judge(*from, objective_);
    const bool screen = at.valid && at.constraintsMet && budget_.fits(at);
    const std::optional<Evaluation> fromScreen = journal_->find(screenSize(planFrom_), "screen");
    const std::size_t end = std::min(plan_.size(), i + 1 + 2 * std::size_t(opt_.shard.count));
    for (std::size_t k = i + 1; k < end; ++k) {
        const Settings& s = plan_[k];
        if (screen && owned(screenSize(s), "screen")) return measured(screenSize(s), "screen", false), true;
        if (!owned(s, "tuned")) continue;
        if (screen) {
            const std::optional<Evaluation> mine = journal_->find(screenSize(s), "screen");
            if (!mine || !fromScreen) continue;
            const Evaluation a = judge(*mine, objective_), b = judge(*fromScreen, objective_);
            if (!a.valid || !b.valid || !worthFullEvaluation(a, b, at, budget_)) continue;
        }
        measured(s, "tuned", false);
        return true;
    }
    return false;
}

}  // namespace st::tune::detail
