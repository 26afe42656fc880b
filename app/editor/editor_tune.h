#pragma once
// The Tune panel's runs, as the Sweep panel's (editor_sweep.h): a child process of the product's
// own `shadowtune tune`, with its own GL context, journal and resume; Cancel is its Ctrl-C (it
// keeps what it measured). The editor never blocks: it polls the child with waitpid(WNOHANG) and
// reads the tune's progress.json (rewritten atomically before each evaluation), then, at the end,
// its summary.json and explain.json.
//
// Each run gets a fresh folder under $TMPDIR: base.json (the live settings, scene path made
// absolute), current.json (the budget "as cheap as now"), A.json (drawn on the front), log.txt
// (the child's output) and out/ (the tune's outputs, kept for the user).
#include "app/editor/child_run.h"
#include "renderer/settings/settings.h"
#include "ui/tune_view.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace st::app {

// The child's arguments after the executable: `tune DIR/base.json --out DIR/out ...`.
std::vector<std::string> tuneArguments(const ui::TuneRequest& r, const std::filesystem::path& dir, bool withA);

// The panel's view of a progress.json: counts, best so far, budget, and the chart's points (the
// evaluations, the input as "current", a compared preset "A"), its feasible front marked.
void readTuneProgress(const nlohmann::json& progress, ui::TuneView& view);

// explain.json's changes as lines the panel can apply one at a time.
std::vector<ui::TuneChange> readExplanation(const nlohmann::json& explain);

// summary.json as two sentences: the tuned result against the current settings, and the held-out
// view's verdict ("" without one).
std::pair<std::string, std::string> readSummary(const nlohmann::json& summary);

// The `tune --objective` choices with the figure table's labels, for the panel's combo.
std::vector<std::pair<std::string, std::string>> tuneObjectives();

class EditorTune {
public:
    explicit EditorTune(std::filesystem::path executable);
    ~EditorTune();  // a child still running is interrupted and waited for
    EditorTune(const EditorTune&) = delete;
    EditorTune& operator=(const EditorTune&) = delete;

    void start(const ui::TuneRequest& request, const Settings& live, const std::optional<Settings>& a,
               const std::filesystem::path& presetDir);
    void cancel();  // SIGINT: the child stops after the evaluation under way
    void poll();    // once per frame; never blocks
    const ui::TuneView& view() const { return view_; }
    bool running() const { return child_.running(); }

private:
    void fail(std::vector<std::string> errors);
    void readProgress();
    void finish(int status);

    std::filesystem::path executable_;
    std::filesystem::path dir_;
    ChildRun child_{std::chrono::milliseconds(250)};  // its output is looked at at most this often
    std::filesystem::file_time_type progressTime_{};
    ui::TuneView view_;
};

}  // namespace st::app
