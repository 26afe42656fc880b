// References and the budget: the engine's or a preset's defaults, --budget-*, the flicker limit.
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

double Tuner::flickerLimit(const Evaluation& input) {
    auto f = [](const Evaluation& e) {
        const auto it = e.figures.find(kFlickerKey);
        return it != e.figures.end() && it->is_number() ? it->get<double>() : 0.0;
    };
    if (refs_.empty()) return f(input);
    double limit = 0.0;
    for (const auto& [name, r] : refs_) limit = std::max(limit, f(measured(r, "tuned")));
    return limit;
}

void Tuner::references() {
    for (const fs::path& file : opt_.budgetFrom) {
        std::vector<std::string> adapted;
        const Settings ref = loadPreset(file);
        refs_.push_back({file.stem().string(), sweep::referenceOnBase(input_, ref, file.stem().string(), adapted)});
        for (const std::string& a : adapted) say("note: reference " + a);
    }
    // For an engine with no budget given: its defaults on this scene and views set the budget
    // and are the baseline the tune must beat.
    if (opt_.engine && !opt_.budgetMs && !opt_.budgetMiB && opt_.budgetFrom.empty())
        refs_.push_back({xport::engineName(*opt_.engine) + "-defaults",
                         xport::engineModel(*opt_.engine, xport::defaultKnobs(*opt_.engine), input_)});
    for (const fs::path& file : opt_.compareWith) {
        std::vector<std::string> adapted;
        compared_.push_back({file.stem().string(), sweep::referenceOnBase(input_, loadPreset(file), file.stem().string(), adapted)});
    }
}

Json Tuner::identity() const {
    Json refs = Json::array();
    for (const auto& [name, s] : refs_) refs.push_back({{"name", name}, {"settings", toOrderedJson(s)}});
    Json j = {{"version", kTuneVersion},
            {"input", toOrderedJson(input_)},
            {"objective", opt_.objective},
            {"budgetMs", opt_.budgetMs ? Json(*opt_.budgetMs) : Json(nullptr)},
            {"budgetMiB", opt_.budgetMiB ? Json(*opt_.budgetMiB) : Json(nullptr)},
            {"budgetFrom", refs},
            {"views", opt_.views},
            {"holdOutEvery", opt_.holdOutEvery},
            {"seed", opt_.seed},
            {"costProfile", metrics::profileName(*opt_.profile)}};
    if (opt_.engine) j["engine"] = xport::engineName(*opt_.engine);
    // Only when not the default, so folders of earlier tunes still resume.
    if (!opt_.constraints) j["constraints"] = "none";
    if (opt_.front) j["front"] = true;
    return j;
}

void Tuner::resolveBudget() {
    if (opt_.budgetMs) budget_.ms = *opt_.budgetMs;
    if (opt_.budgetMiB) budget_.bytes = *opt_.budgetMiB * kMiB;
    for (const auto& [name, s] : refs_) {
        const Evaluation e = judge(measured(s, "tuned"), {opt_.objective, {}});
        if (!e.valid) throw std::runtime_error("reference " + name + ": " + e.problem);
        say("reference " + name + ": " + fixed(e.costMs, 1) + " ms modelled, " + fixed(e.mapBytes / kMiB, 1) + " MiB, " +
            errorText(opt_.objective, e.error) + " " + sweep::errorFigure(opt_.objective).label);
        if (!opt_.budgetMs) budget_.ms = std::min(budget_.ms.value_or(e.costMs), e.costMs);
        if (!opt_.budgetMiB) budget_.bytes = std::min(budget_.bytes.value_or(e.mapBytes), e.mapBytes);
    }
    if (!budget_.ms && !budget_.bytes) throw std::runtime_error("give a budget: --budget-ms, --budget-mib or --budget-from");
    say("budget: " + budgetText(budget_) + " (modelled with " + metrics::profileName(*opt_.profile) + ")");
}

}  // namespace st::tune::detail
