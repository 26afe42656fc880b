#include "app/editor/editor_app.h"

#include "app/editor/editor_session.h"
#include "app/editor/editor_window.h"
#include "app/editor/frame_pacer.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/image/image_io.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>

namespace st::app {
namespace {
constexpr std::chrono::minutes kAccuracyTimeout{10};  // a scripted run must end even if the job hangs

void writeStatus(const std::filesystem::path& file, const EditorWindow& window, const EditorSession& session, bool idle) {
    nlohmann::json j{{"pid", ::getpid()}, {"frames", session.framesDrawn()}, {"idle", idle},
                           {"accuracy", session.accuracy().summary()}, {"split", session.splitShown()},
                           {"swapped", session.swapped()},
                           {"title", window.title()}, {"message", session.message()}};
    const CameraSettings& c = session.camera();
    j["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}}, {"target", {c.target.x, c.target.y, c.target.z}}};
    // The last scene renders (wall ms, scale): a change's first frame against the ones after it.
    j["renders"] = nlohmann::json::array();
    for (const auto& [ms, scale] : session.frameTimes().lastRenders(8)) j["renders"].push_back({{"ms", ms}, {"scale", scale}});
    // Where the memory goes (the Help window's Memory table): bytes by kind and the resident set.
    const ui::MemoryView memory = session.memory();
    j["memory"] = {{"resident", memory.residentBytes}, {"objects", memory.total()}, {"lines", nlohmann::json::object()}};
    for (const ui::MemoryLine& l : memory.lines) j["memory"]["lines"][l.what] = l.bytes;
    writeTextAtomic(file, j.dump() + "\n");
}

// Frames until the window closes, or until opt.frames have run (and, with opt.waitAccuracy, the
// Accuracy panel has its figures); the last frame writes the screenshot. Between frames the
// window waits as the FramePacer says (issue 21 #2); a scripted run (--frames) never waits, as
// nothing would wake it.
void runFrames(EditorWindow& window, EditorSession& session, const EditorOptions& opt) {
    const auto start = std::chrono::steady_clock::now();
    int finishedFrames = 0;
    FramePacer pacer;
    for (int frame = 0;; ++frame) {
        // The figures reach the panel the frame after the job ends, and ImGui sizes a new table's
        // columns over its first frames: the screenshot waits a few frames more.
        finishedFrames = session.accuracy().finished() ? finishedFrames + 1 : 0;
        const bool waiting = (opt.waitAccuracy && finishedFrames < 4) || session.previewPending();
        if (waiting && std::chrono::steady_clock::now() - start > kAccuracyTimeout)
            throw std::runtime_error("the Accuracy panel's job or the path preview did not end within 10 minutes");
        const bool last = opt.frames > 0 && frame + 1 >= opt.frames && !waiting;
        session.frame(last && opt.screenshot ? &*opt.screenshot : nullptr, last);
        if (last || session.quitRequested()) break;
        const FramePacer::Wait wait = pacer.after(session.activity());
        if (opt.statusFile) writeStatus(*opt.statusFile, window, session, pacer.idle() && opt.frames == 0);
        if (opt.frames > 0 || wait == FramePacer::Wait::None) continue;
        window.waitEvents(wait == FramePacer::Wait::Timeout ? FramePacer::kJobPollSeconds : -1.0);
    }
}

// One run from the window opening to the last frame's outputs; `closing` is set when the run
// decides to end, before the session and the window are torn down.
int runSession(const EditorOptions& opt, std::chrono::steady_clock::time_point& closing) {
    EditorWindow window("shadowtune", opt.debugContext);
    EditorSession session(window, opt);
    runFrames(window, session, opt);
    if (opt.waitAccuracy) std::printf("%s\n", session.accuracy().summary().c_str());
    if (opt.previewPath) std::printf("%s\n", session.previewLine().c_str());
    if (opt.sceneShot) session.writeSceneShot(*opt.sceneShot);
    if (opt.saveAs) session.saveAs(*opt.saveAs);
    if (opt.layoutReport) session.writeLayoutReport(*opt.layoutReport);
    session.printFrameTimes();
    closing = std::chrono::steady_clock::now();
    if (opt.debugContext && gpu::seriousDebugMessageCount() > 0) {
        std::fprintf(stderr, "error: GL debug output reported %d errors (see above)\n", gpu::seriousDebugMessageCount());
        return 3;
    }
    if (opt.waitAccuracy && !session.accuracy().done()) return 4;  // the summary says why
    return 0;
}

}  // namespace

int runEditor(const EditorOptions& opt) {
    try {
        std::chrono::steady_clock::time_point closing;
        const int code = runSession(opt, closing);
        // Closing = stopping the Accuracy job, saving the window and layout files, GL and GLFW
        // teardown: the user waits for it after pressing the close button.
        std::printf("closed in %.0f ms\n",
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - closing).count());
        return code;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}

}  // namespace st::app
