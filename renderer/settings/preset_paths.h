#pragma once
// File references inside a preset are relative to the preset's own folder. A preset written to
// another folder must have them rewritten, or it names files that are not there (issue 13 #1).
// The only file reference a preset holds today is `scene`; rebasePaths is the one place that
// knows the list.
#include "renderer/settings/settings.h"

#include <filesystem>
#include <string>

namespace st {

// The folder a file's relative references start from: its parent, or "." for a bare file name
// ("mine.json" has an empty parent_path(), which std::filesystem::absolute and
// create_directories refuse). Use it wherever a path's folder is needed.
std::filesystem::path folderOf(const std::filesystem::path& file);

// `ref` as written in a preset in `fromDir`, rewritten for a preset in `toDir`: relative again
// where a relative path exists, else absolute. "builtin:..." names, absolute paths and "" are
// returned as they are.
std::string rebaseFileReference(const std::string& ref, const std::filesystem::path& fromDir,
                                const std::filesystem::path& toDir);

// `s` with every file reference rebased from `fromDir` to `toDir`.
Settings rebasePaths(Settings s, const std::filesystem::path& fromDir, const std::filesystem::path& toDir);

// savePresetAtomic of `s`, whose references (and `schemaRef`, a "$schema" to write, "" for none)
// are relative to `fromDir`, rebased for `file`'s folder.
void savePresetRebased(const Settings& s, const std::filesystem::path& fromDir, const std::filesystem::path& file,
                       const std::string& schemaRef = "");

// The "$schema" a preset file names: "" when it names none or cannot be read. It carries no
// setting (Settings has no field for it), but editors find the JSON Schema through it, so a save
// of the preset elsewhere keeps it (rebaseSchemaRef).
std::string presetSchemaRef(const std::filesystem::path& file);
// A "$schema" for a preset saved as `file` that has none yet: schema/preset.schema.json of the
// nearest folder above `file` that holds one, else above `hint` (the editor's presets folder),
// relative to `file`'s folder; "" when neither has one.
std::string defaultSchemaRef(const std::filesystem::path& file, const std::filesystem::path& hint = {});

// A "$schema" written in a preset in `fromDir`, for a preset in `toDir`: a URL stays as it is, a
// path is rebased as the scene is (rebaseFileReference).
std::string rebaseSchemaRef(const std::string& ref, const std::filesystem::path& fromDir, const std::filesystem::path& toDir);

}  // namespace st
