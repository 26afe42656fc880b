// Outputs while and after the run: progress.json, tuned.json and the explanation, the engine's text, front/.
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

void Tuner::progress(const SearchProgress& p) {
    std::string line = "tune [" + std::to_string(p.evaluations + 1) + "/" + std::to_string(p.limit) + "] ";
    if (p.screenings) line += "(" + std::to_string(p.screenings) + " screened) ";
    if (p.best) {
        const Candidate& b = (*p.evaluated)[*p.best];
        line += "best " + errorText(opt_.objective, b.eval.error) + " at " + fixed(b.eval.costMs, 1) + " ms";
    } else {
        line += "nothing within the budget yet";
    }
    say(line + "; trying " + p.trying);
    writeProgress("searching", p.evaluations, p.limit, p.evaluated);
}

Json Tuner::pointJson(const Evaluation& e) const {
    return {{"error", e.error}, {"costMs", e.costMs}, {"mapBytes", e.mapBytes}};
}

void Tuner::writeProgress(const std::string& stage, int done, int limit, const std::vector<Candidate>* evaluated) {
    if (!writes()) return;
    Json refs = Json::object();
    for (const auto* list : {&refs_, &compared_})
        for (const auto& [name, r] : *list) {
            Json j = pointJson(judge(measured(r, "tuned", list == &refs_), objective_));
            j["budget"] = list == &refs_;
            refs[name] = std::move(j);
        }
    Json points = Json::array();
    std::optional<std::size_t> best;
    if (evaluated)
        for (std::size_t i = 0; i < evaluated->size(); ++i) {
            const Candidate& c = (*evaluated)[i];
            if (!c.eval.valid) continue;
            Json j = pointJson(c.eval);
            j["feasible"] = c.feasible;
            j["onFront"] = onFront(c);
            points.push_back(std::move(j));
            if (c.feasible && (!best || better(c, (*evaluated)[*best]))) best = i;
        }
    const Json progress = {{"version", kTuneVersion},
                           {"stage", stage},
                           {"evaluations", done},
                           {"limit", limit},
                           {"screeningLimit", screeningLimit_},
                           {"objective", opt_.objective},
                           {"budgetMs", budget_.ms ? Json(*budget_.ms) : Json(nullptr)},
                           {"budgetBytes", budget_.bytes ? Json(*budget_.bytes) : Json(nullptr)},
                           {"input", pointJson(judge(measured(input_, "tuned"), objective_))},
                           {"references", refs},
                           {"best", best ? pointJson((*evaluated)[*best].eval) : Json(nullptr)},
                           {"secondsAllRuns", secondsAllRuns()},
                           {"points", points}};
    writeTextAtomic(opt_.outDir / "progress.json", progress.dump() + "\n");
}

Json Tuner::evalJson(const Evaluation& e) const {
    return {{"error", e.error}, {"costMs", e.costMs}, {"mapBytes", e.mapBytes}, {"constraintsMet", e.constraintsMet},
            {"violated", e.violated}, {"figures", e.figures}};
}

void Tuner::writeEngineOutputs(xport::Engine e, const Settings& best) const {
    const xport::EngineKnobs k = xport::knobsFor(e, best);
    const std::string name = xport::engineName(e);
    writeTextAtomic(opt_.outDir / (name + ".json"), Json{{"engine", name}, {"knobs", k.knobs}, {"lacks", k.lacks}}.dump(2) + "\n");
    for (const xport::PasteText& t : xport::engineSnippets(e, k.knobs)) {
        writeTextAtomic(opt_.outDir / t.file, t.text);
        say("wrote " + (opt_.outDir / t.file).string());
    }
    if (!k.lacks.empty()) say("  " + name + " lacks: " + k.lacks.front());
}

void Tuner::writeOutputs(const Candidate& best, double seconds) {
    const fs::path& dir = opt_.outDir;
    if (writes()) {
        const Json tuned = sweep::presetInFolder(dir, presetDir_, toOrderedJson(best.settings));
        writeTextAtomic(dir / "tuned.json", tuned.dump(2) + "\n");
        loadPreset(dir / "tuned.json");  // never leave a preset that does not load again
        if (opt_.engine) writeEngineOutputs(*opt_.engine, best.settings);
        writeFront(&best);
    }
    // Every shard makes the measurements below, in the same order, so they share them.
    const Evaluator judged = [this](const Settings& s) { return judge(measured(s, "tuned"), objective_); };
    const Evaluation inputEval = judged(input_);
    const Explanation why = explain(input_, inputEval, best.settings, best.eval, opt_.objective, judged);
    if (writes()) {
        writeTextAtomic(dir / "explain.json", toJson(why).dump(2) + "\n");
        writeTextAtomic(dir / "explain.md", toMarkdown(why, "Why " + opt_.preset.stem().string() + " was tuned this way"));
        for (const std::string& w : why.worse) say("  worse than the input: " + w);
        for (const Explained& x : why.changes) say("  " + x.line);
    }
    writeSummary(best, inputEval, seconds);
}

std::vector<const Candidate*> Tuner::frontPoints() const {
    std::vector<const Candidate*> out;
    for (std::size_t i : costErrorFront(result_.evaluated, [this](const Candidate& c) { return onFront(c); }))
        out.push_back(&result_.evaluated[i]);
    return out;
}

Json Tuner::frontJson() const {
    Json front = Json::array();
    for (const Candidate* c : frontPoints())
        front.push_back({{"costMs", c->eval.costMs}, {"mapBytes", c->eval.mapBytes}, {"error", c->eval.error},
                         {"constraintsMet", c->eval.constraintsMet}, {"violated", c->eval.violated},
                         {"id", settingsId(c->settings)}, {"move", c->move}});
    return front;
}

void Tuner::sayFront() const {
    const std::vector<const Candidate*> f = frontPoints();
    if (f.empty()) return say("front: no point within the budget");
    say("front: " + std::to_string(f.size()) + " points within the budget, from " + fixed(f.front()->eval.costMs, 1) + " ms (" +
        errorText(opt_.objective, f.front()->eval.error) + ") to " + fixed(f.back()->eval.costMs, 1) + " ms (" +
        errorText(opt_.objective, f.back()->eval.error) + "); " + std::to_string(result_.frontRungs) +
        " evaluations on the descent -> " + (opt_.outDir / "front" / "front.json").string());
}

void Tuner::writeFront(const Candidate* best) {
    sweep::Manifest m;
    m.sweep = opt_.preset.stem().string();  // the chart's title starts with it: keep it short
    m.scene = input_.scene;
    m.presetDir = presetDir_;
    m.width = input_.output.width;
    m.height = input_.output.height;
    m.machine = opt_.machine;
    m.costProfile = metrics::profileName(*opt_.profile);
    std::vector<sweep::PointResult> points;
    auto add = [&](const Settings& s, const Evaluation& e, std::string label, bool reference) {
        if (!e.valid) return;
        sweep::PointResult r{settingsId(s), std::move(label), reference, {}, toOrderedJson(s), {}};
        for (const auto& [key, value] : e.figures.items()) r.figures.push_back({key, value.is_number() ? value.get<double>() : NAN});
        m.pointIds.push_back(r.id);
        points.push_back(std::move(r));
    };
    add(input_, measured(input_, "tuned"), "input", true);
    for (const auto& [name, s] : refs_) add(s, measured(s, "tuned"), name, true);
    for (const auto& [name, s] : compared_) add(s, measured(s, "tuned", false), name, true);
    // Labels stay short for the chart's front table: the moves that led to a point are in
    // evaluations.jsonl and explain.md.
    for (std::size_t i = 0; i < result_.evaluated.size(); ++i) {
        const Candidate& c = result_.evaluated[i];
        if (onFront(c) && !(c.settings == input_))
            add(c.settings, c.eval, &c == best ? "tuned" : "evaluation " + std::to_string(i + 1), false);
    }
    sweep::writeReport(opt_.outDir / "front", m, points, {opt_.objective, "model"});
}

}  // namespace st::tune::detail
