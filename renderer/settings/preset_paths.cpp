#include "renderer/settings/preset_paths.h"

#include "renderer/settings/settings_json.h"

namespace fs = std::filesystem;

namespace st {
namespace {

fs::path absoluteFolder(const fs::path& dir) {
    std::error_code ec;  // no current folder: the path is kept as given
    const fs::path abs = fs::absolute(dir.empty() ? fs::path(".") : dir, ec);
    return (ec ? dir : abs).lexically_normal();
}

}  // namespace

fs::path folderOf(const fs::path& file) {
    fs::path dir = file.parent_path();
    return dir.empty() ? fs::path(".") : dir;
}

std::string rebaseFileReference(const std::string& ref, const fs::path& fromDir, const fs::path& toDir) {
    if (ref.empty() || ref.starts_with("builtin:") || fs::path(ref).is_absolute()) return ref;
    const fs::path target = (absoluteFolder(fromDir) / ref).lexically_normal();
    const fs::path relative = target.lexically_relative(absoluteFolder(toDir));
    return relative.empty() ? target.string() : relative.string();
}

Settings rebasePaths(Settings s, const fs::path& fromDir, const fs::path& toDir) {
    s.scene = rebaseFileReference(s.scene, fromDir, toDir);
    return s;
}

void savePresetRebased(const Settings& s, const fs::path& fromDir, const fs::path& file, const std::string& schemaRef) {
    const fs::path toDir = folderOf(file);
    savePresetAtomic(rebasePaths(s, fromDir, toDir), file, schemaRef.empty() ? "" : rebaseSchemaRef(schemaRef, fromDir, toDir));
}

std::string presetSchemaRef(const fs::path& file) {
    try {
        const nlohmann::json j = loadJsonFile(file);
        const auto it = j.is_object() ? j.find("$schema") : j.end();
        return it != j.end() && it->is_string() ? it->get<std::string>() : "";
    } catch (const SettingsError&) {
        return "";
    }
}

std::string defaultSchemaRef(const fs::path& file, const fs::path& hint) {
    std::error_code ec;
    const fs::path folder = fs::absolute(folderOf(file), ec).lexically_normal();
    for (const fs::path& start : {folder, hint.empty() ? fs::path() : fs::absolute(hint, ec).lexically_normal()}) {
        for (fs::path dir = start; !dir.empty(); dir = dir.parent_path()) {
            const fs::path schema = dir / "schema" / "preset.schema.json";
            if (fs::is_regular_file(schema, ec)) return schema.lexically_relative(folder).generic_string();
            if (dir == dir.parent_path()) break;
        }
    }
    return "";
}

std::string rebaseSchemaRef(const std::string& ref, const fs::path& fromDir, const fs::path& toDir) {
    return ref.find("://") != std::string::npos ? ref : rebaseFileReference(ref, fromDir, toDir);
}

}  // namespace st
