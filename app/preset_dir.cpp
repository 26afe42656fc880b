#include "app/preset_dir.h"

namespace st::app {
namespace fs = std::filesystem;

namespace {
fs::path presetsFolderHolding(const fs::path& cwd, const fs::path& opened) {
    if (opened.empty()) return {};
    const fs::path file = (opened.is_absolute() ? opened : cwd / opened).lexically_normal();
    for (fs::path dir = file.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
        if (dir.filename() == "presets") return dir;
    return {};
}
}  // namespace

fs::path presetDirFor(const fs::path& cwd, const fs::path& exe, const fs::path& opened) {
    std::error_code ec;
    if (fs::is_directory(cwd / "presets", ec)) return "presets";
    if (fs::path holding = presetsFolderHolding(cwd, opened); !holding.empty() && fs::is_directory(holding, ec))
        return holding;
    const fs::path installed = (exe.parent_path() / ".." / "share" / "shadowtune" / "presets").lexically_normal();
    if (!exe.empty() && fs::is_directory(installed, ec)) return installed;
    return "presets";
}

fs::path defaultPresetDir(const fs::path& opened) {
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return presetDirFor(cwd, ec ? fs::path() : exe, opened);
}

}  // namespace st::app
