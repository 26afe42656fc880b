#include "ui/document.h"

#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"

#include <exception>

namespace st::ui {

Settings documentPart(const Document& doc, Settings s) {
    if (!doc.saveViewWithPreset && doc.clean) s.output.view = doc.clean->output.view;
    return s;
}

bool isDirty(const Document& doc, const Settings& s) { return doc.clean && *doc.clean != documentPart(doc, s); }

bool loadDocument(Document& doc, const std::filesystem::path& file, Settings& s) {
    try {
        Settings loaded = loadPreset(file);
        doc.schema = presetSchemaRef(file);  // a few kilobytes: read twice rather than widen loadPreset
        s = loaded;
        doc.file = file;
        doc.clean = std::move(loaded);
        doc.errors.clear();
        doc.status = "Loaded " + file.string();
        return true;
    } catch (const SettingsError& e) {
        doc.errors = e.messages();
    } catch (const std::exception& e) {
        doc.errors = {file.string() + ": " + e.what()};
    }
    doc.status.clear();
    return false;
}

bool saveDocument(Document& doc, const Settings& s, const std::filesystem::path& file) {
    if (file.empty()) {
        doc.errors = {"Save: no file name given"};
        return false;
    }
    try {
        const Settings saved = documentPart(doc, s);
        // A URL stays as it is; a path follows the file into its folder, as the scene does.
        std::string schema = doc.file.empty() ? doc.schema : rebaseSchemaRef(doc.schema, folderOf(doc.file), folderOf(file));
        // A preset without one gets the repository's, wherever it is saved (issue 39 #10).
        if (schema.empty()) schema = defaultSchemaRef(file, doc.schemaHint);
        const std::filesystem::path folder = file.parent_path();
        std::error_code ec;
        const bool created = !folder.empty() && !std::filesystem::exists(folder, ec) && std::filesystem::create_directories(folder, ec);
        savePresetAtomic(saved, file, schema);
        doc.file = file;
        doc.clean = saved;
        doc.schema = schema;
        doc.errors.clear();
        doc.status = "Saved " + file.string() + (created ? " (created the folder " + folder.string() + ")" : "");
        return true;
    } catch (const SettingsError& e) {
        doc.errors = e.messages();
    } catch (const std::exception& e) {
        doc.errors = {file.string() + ": " + e.what()};
    }
    doc.status.clear();
    return false;
}

std::filesystem::path resolveSavePath(const std::filesystem::path& presetDir, const std::string& text) {
    if (text.empty()) return {};
    std::filesystem::path path(text);
    if (path.is_relative()) path = presetDir / path;
    if (!path.has_extension()) path += ".json";
    return path;
}

std::string documentTitle(const Document& doc, bool dirty) {
    const std::string name = doc.file.empty() ? "untitled" : doc.file.filename().string();
    return "shadowtune - " + name + (dirty ? " *" : "");
}

}  // namespace st::ui
