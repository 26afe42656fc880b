#include "app/preset_batch.h"

#include <cstdio>
#include <exception>
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

}  // namespace st::app
