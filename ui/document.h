#pragma once
// The preset being edited: which file, what it held when last loaded or saved (for the dirty
// marker) and what went wrong last. Pure: loading and saving go through settings_json, and
// failures become messages for the UI, never exceptions.
#include "renderer/settings/settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace st::ui {

struct Document {
    std::filesystem::path file;        // empty: untitled
    std::optional<Settings> clean;     // as last loaded or saved; nullopt until known
    std::vector<std::string> errors;   // of the last failed load or save
    std::string status;                // of the last successful one: "Saved presets/a.json"
    std::string schema;                // the file's "$schema" (relative to its folder), kept by saves
    std::filesystem::path schemaHint;  // where a preset without one finds schema/ (the presets folder)
    // The debug view (output.view) is editor state: off, changing it neither dirties the document
    // nor is saved; the file keeps the view it had (issue 13 #4).
    bool saveViewWithPreset = false;
};

// What of `s` belongs to the document: `s`, with the view the file has unless saveViewWithPreset.
Settings documentPart(const Document& doc, Settings s);

bool isDirty(const Document& doc, const Settings& s);  // false while `clean` is unknown

// loadPreset(file) into s. On failure s is untouched, doc.errors lists every problem and the
// result is false. On success the document becomes `file`, clean.
bool loadDocument(Document& doc, const std::filesystem::path& file, Settings& s);

// savePresetAtomic(documentPart(s), file), with the document's "$schema" rebased for `file`'s
// folder; a missing folder is created (the status says so). On failure (invalid settings,
// unwritable folder) doc.errors says why.
bool saveDocument(Document& doc, const Settings& s, const std::filesystem::path& file);

// A path typed in "Save as": relative paths are taken from presetDir, ".json" is added when the
// name has no extension. Empty text gives an empty path.
std::filesystem::path resolveSavePath(const std::filesystem::path& presetDir, const std::string& text);

// "shadowtune - default.json *" (untitled when there is no file; '*' when dirty).
std::string documentTitle(const Document& doc, bool dirty);

}  // namespace st::ui
