#include "app/cli/preset_batch.h"

#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/settings/settings_json.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

namespace st::app {
namespace fs = std::filesystem;

void makeOutputDir(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": cannot create output folder: " +
                                 (ec ? ec.message() : "not a directory"));
}

int forEachPreset(const std::vector<fs::path>& presets, const std::function<void(const fs::path&)>& one) {
    int failed = 0;
    for (const fs::path& preset : presets) {
        try {
            one(preset);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "error: %s\nskipped %s\n", e.what(), preset.string().c_str());
            ++failed;
        }
    }
    if (failed) std::fprintf(stderr, "%d of %zu presets failed\n", failed, presets.size());
    return failed ? 1 : 0;
}

int runHeadless(const HeadlessRunOptions& opt, const PresetWorkFactory& start) {
    std::unique_ptr<HeadlessContext> ctx;
    PresetWork work;
    try {
        makeOutputDir(opt.outDir);
        ctx = HeadlessContext::create(opt.debugContext);
        if (opt.debugContext) gpu::enableDebugOutput();
        work = start();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
    const int code = forEachPreset(opt.presets, [&](const fs::path& preset) {
        const int before = gpu::seriousDebugMessageCount();
        const PresetWriter write = work(preset);
        if (opt.debugContext && gpu::seriousDebugMessageCount() > before)
            throw std::runtime_error(preset.string() + ": GL debug output reported errors (see above)");
        if (write) write();
    });
    work = nullptr;  // the command's GL objects go while the context is still current
    return code;
}

}  // namespace st::app
