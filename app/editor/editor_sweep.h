#pragma once
// The Sweep panel's runs. Decision: a sweep runs as a child process of the product's own
// `shadowtune sweep`, not on a thread of the editor. The child has its own GL context (the
// editor's is bound to the window's thread), its own Embree BVH and memory, the sweep library's
// resume and atomic per-point writes, and cancel is its Ctrl-C (SIGINT: stop after the current
// point, results intact). A crash or a GL error there cannot take the editor down, and the editor
// never blocks: it polls the child with waitpid(WNOHANG) and reads progress from the point files
// the child writes (DIR/points/<id>.json), not from its terminal output.
//
// Each run gets a fresh folder under $TMPDIR: base.json (the live settings, scene path made
// absolute), current.json and A.json (references: drawn as marked points), sweep.json, log.txt
// (the child's output) and out/ (the sweep's results and charts, kept for the user).
#include "app/editor/child_run.h"
#include "renderer/settings/settings.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"
#include "ui/compare_view.h"


#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

// The sweep file for `request` over `base`: its axes as the panel gave them, the output size,
// references "current" (always) and "A" (when given). Writes base.json, current.json, A.json
// and sweep.json into `dir`; `presetDir` is where base's relative scene path starts.
std::filesystem::path writeEditorSweep(const std::filesystem::path& dir, const ui::SweepRequest& request,
                                       const Settings& base, const std::optional<Settings>& a,
                                       const std::filesystem::path& presetDir);

// A point result as the chart shows it. `axisFields`: the manifest's.
ui::SweepPoint chartPoint(const sweep::PointResult& r, const std::vector<std::string>& axisFields);

// The chart's points with both Pareto fronts marked (report::paretoFront).
std::vector<ui::SweepPoint> chartPoints(const std::vector<sweep::PointResult>& results,
                                        const std::vector<std::string>& axisFields);

class EditorSweep {
public:
    // executable: the shadowtune binary to run (the editor passes its own, /proc/self/exe).
    explicit EditorSweep(std::filesystem::path executable, int costFrames = 3);
    ~EditorSweep();  // a child still running is interrupted and waited for
    EditorSweep(const EditorSweep&) = delete;
    EditorSweep& operator=(const EditorSweep&) = delete;

    // Writes the sweep and starts the child; a refused sweep (the sweep reader's messages) or a
    // failed start becomes a Failed view. Ignored while a run is going.
    void start(const ui::SweepRequest& request, const Settings& live, const std::optional<Settings>& a,
               const std::filesystem::path& presetDir);
    void cancel();  // SIGINT: the child stops after the point it is measuring
    void poll();    // once per frame: progress, new points, the child's end; never blocks
    const ui::SweepView& view() const { return view_; }
    bool running() const { return child_.running(); }
    const std::filesystem::path& folder() const { return dir_; }

private:
    void fail(std::vector<std::string> errors);
    void readNewPoints();
    void finish(int status);

    std::filesystem::path executable_;
    int costFrames_;
    std::filesystem::path dir_;
    ChildRun child_{std::chrono::milliseconds(250)};  // its output is looked at at most this often
    std::optional<sweep::SweepSpec> spec_;
    std::optional<sweep::Manifest> manifest_;
    std::size_t readCount_ = 0;   // point files in view_.points
    ui::SweepView view_;
};

}  // namespace st::app
