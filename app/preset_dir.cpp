#include "app/preset_dir.h"

namespace st::app {
namespace fs = std::filesystem;

fs::path presetDirFor(const fs::path& cwd, const fs::path& exe) {
    std::error_code ec;
    if (fs::is_directory(cwd / "presets", ec)) return "presets";
    const fs::path installed = (exe.parent_path() / ".." / "share" / "shadowtune" / "presets").lexically_normal();
    if (!exe.empty() && fs::is_directory(installed, ec)) return installed;
    return "presets";
}

fs::path defaultPresetDir() {
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return presetDirFor(cwd, ec ? fs::path() : exe);
}

}  // namespace st::app
