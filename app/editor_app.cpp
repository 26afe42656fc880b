#include "app/editor_app.h"

#include "app/editor_session.h"
#include "app/editor_window.h"
#include "renderer/gpu/debug_output.h"

#include <cstdio>
#include <exception>

namespace st::app {

int runEditor(const EditorOptions& opt) {
    try {
        EditorWindow window("shadowtune", opt.debugContext);
        EditorSession session(window, opt);
        for (int frame = 0;; ++frame) {
            bool last = opt.frames > 0 && frame + 1 >= opt.frames;
            session.frame(last && opt.screenshot ? &*opt.screenshot : nullptr);
            if (last || session.quitRequested()) break;
        }
        if (opt.sceneShot) session.writeSceneShot(*opt.sceneShot);
        if (opt.saveAs) session.saveAs(*opt.saveAs);
        session.printFrameTimes();
        if (opt.debugContext && gpu::seriousDebugMessageCount() > 0) {
            std::fprintf(stderr, "error: GL debug output reported %d errors (see above)\n", gpu::seriousDebugMessageCount());
            return 3;
        }
        return session.exitCode();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}

}  // namespace st::app
