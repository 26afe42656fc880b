#include "tests/layers/layer_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace st::layers {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool isFolder(const std::string& entry) { return !entry.empty() && entry.back() == '/'; }

// Fetches a string or a list of strings at `at`, naming the file and the JSON path when it is not.
std::string stringAt(const json& node, const std::string& key, const std::string& where) {
    if (!node.contains(key) || !node[key].is_string())
        throw std::runtime_error(where + "/" + key + ": expected a string");
    return node[key].get<std::string>();
}

std::vector<std::string> stringsAt(const json& node, const std::string& key, const std::string& where) {
    std::vector<std::string> out;
    if (!node.contains(key)) return out;
    if (!node[key].is_array()) throw std::runtime_error(where + "/" + key + ": expected an array of strings");
    for (std::size_t i = 0; i < node[key].size(); ++i) {
        if (!node[key][i].is_string())
            throw std::runtime_error(where + "/" + key + "/" + std::to_string(i) + ": expected a string");
        out.push_back(node[key][i].get<std::string>());
    }
    return out;
}

// A use is "name" or {"what": "name", "from": ["file", ...]}.
std::vector<Use> usesAt(const json& node, const std::string& key, const std::string& where) {
    std::vector<Use> out;
    if (!node.contains(key)) return out;
    if (!node[key].is_array()) throw std::runtime_error(where + "/" + key + ": expected an array");
    for (std::size_t i = 0; i < node[key].size(); ++i) {
        const json& u = node[key][i];
        const std::string at = where + "/" + key + "/" + std::to_string(i);
        if (u.is_string()) out.push_back({u.get<std::string>(), {}});
        else if (u.is_object()) out.push_back({stringAt(u, "what", at), stringsAt(u, "from", at)});
        else throw std::runtime_error(at + ": expected a string or {\"what\", \"from\"}");
    }
    return out;
}

// A misspelt key ("may_inlcude") would silently allow nothing or everything: refuse it.
void onlyKeys(const json& node, const std::set<std::string>& keys, const std::string& where) {
    for (const auto& [key, value] : node.items())
        if (!keys.count(key)) throw std::runtime_error(where + "/" + key + ": unknown key");
}

std::string joined(const std::vector<std::string>& items, const std::string& sep) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : sep) + item;
    return out;
}

bool isSource(const fs::path& p) {
    static const std::set<std::string> kExtensions = {".h", ".hpp", ".cpp", ".glsl", ".vert", ".frag", ".comp"};
    return kExtensions.count(p.extension().string()) > 0;
}

const Layer* layerNamed(const Table& table, const std::string& name) {
    for (const Layer& l : table.layers)
        if (l.name == name) return &l;
    return nullptr;
}

bool fromAllowed(const Use& u, const std::string& file) {
    return u.from.empty() || std::find(u.from.begin(), u.from.end(), file) != u.from.end();
}

// Does `use` name the project file `target`, owned by layer `owning`?
bool names(const Use& use, const std::string& target, const Layer& owning) {
    if (use.what == owning.name) return true;
    return isFolder(use.what) ? startsWith(target, use.what) : target == use.what;
}

std::string useText(const Use& u) {
    std::string text = "`" + u.what + "`";
    if (!u.from.empty()) {
        std::vector<std::string> files;
        for (const auto& f : u.from) files.push_back("`" + f + "`");
        text += " (from " + joined(files, ", ") + " only)";
    }
    return text;
}

std::string usesText(const std::vector<Use>& uses) {
    std::vector<std::string> parts;
    for (const Use& u : uses) parts.push_back(useText(u));
    return parts.empty() ? "nothing" : joined(parts, ", ");
}

struct Include {
    int line = 0;
    bool angled = false;
    std::string name;
};

struct GlCall {
    int line = 0;
    std::string function;
};

struct Scan {
    std::vector<Include> includes;
    std::vector<GlCall> glCalls;
};

// The code of a line without its string literals and // comment (block comments are not used).
std::string codeOf(const std::string& line) {
    static const std::regex kString(R"("(\\.|[^"\\])*"|'(\\.|[^'\\])*')");
    std::string code = std::regex_replace(line, kString, "\"\"");
    const auto comment = code.find("//");
    return comment == std::string::npos ? code : code.substr(0, comment);
}

Scan scan(const fs::path& file) {
    static const std::regex kInclude(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    // glClear(, glBlitNamedFramebuffer (: GL's functions; glfwInit and glm:: do not match.
    static const std::regex kGlCall(R"((^|[^A-Za-z0-9_])(gl[A-Z][A-Za-z0-9]*)\s*\()");
    Scan out;
    std::ifstream in(file);
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        std::smatch m;
        if (std::regex_search(text, m, kInclude)) {
            out.includes.push_back({line, m[1] == "<", m[2]});
            continue;
        }
        const std::string code = codeOf(text);
        for (auto it = std::sregex_iterator(code.begin(), code.end(), kGlCall); it != std::sregex_iterator(); ++it)
            out.glCalls.push_back({line, (*it)[2]});
    }
    return out;
}

class Checker {
public:
    Checker(const Table& table, const fs::path& root) : table_(table), root_(root) {}

    void file(const std::string& rel) {
        const Layer* layer = owner(table_, rel);
        if (!layer) {
            add(rel, 0, "", "no layer owns this file: add it (or its folder) to a layer's \"files\" in docs/layers.json");
            return;
        }
        const Scan found = scan(root_ / rel);
        for (const Include& inc : found.includes) include(rel, *layer, inc);
        if (layer->glCalls) return;
        for (const GlCall& call : found.glCalls)
            add(rel, call.line, "", "layer \"" + layer->name + "\" makes the GL call " + call.function +
                                        "(); GL calls belong to the renderer (a layer with \"gl_calls\": true)");
    }

    // Table entries that name nothing: a stale table is as wrong as a stale doc.
    void table() {
        std::set<std::string> names;
        for (const Layer& l : table_.layers) {
            if (!names.insert(l.name).second) add("docs/layers.json", 0, "", "layer \"" + l.name + "\" is listed twice");
            for (const auto& entry : l.files)
                if (!exists(entry)) add("docs/layers.json", 0, "", "layer \"" + l.name + "\" owns " + entry + ", which does not exist");
            for (const Use& u : l.mayInclude) {
                if (!layerNamed(table_, u.what) && !exists(u.what))
                    add("docs/layers.json", 0, "", "layer \"" + l.name + "\" may include \"" + u.what +
                                                       "\", which is neither a layer nor a file of the tree");
                fromFiles(l, u);
            }
            for (const Use& u : l.external) fromFiles(l, u);
        }
    }

    std::vector<Violation> take() { return std::move(violations_); }

private:
    void add(const std::string& file, int line, const std::string& include, const std::string& reason) {
        violations_.push_back({file, line, include, reason});
    }

    bool exists(const std::string& entry) const {
        const fs::path p = root_ / entry;
        return isFolder(entry) ? fs::is_directory(p) : fs::is_regular_file(p);
    }

    void fromFiles(const Layer& l, const Use& u) {
        for (const auto& f : u.from)
            if (!exists(f) || owner(table_, f) != &l)
                add("docs/layers.json", 0, "", "layer \"" + l.name + "\" names " + f + " in \"from\", which is not a file of that layer");
    }

    // The project file an #include "name" reads: from the root (the include directory every target
    // exports), else next to the including file (the shaders' GLSL includes); "" when neither.
    std::string projectFile(const std::string& rel, const std::string& name) const {
        if (fs::is_regular_file(root_ / name)) return fs::path(name).lexically_normal().generic_string();
        const fs::path local = fs::path(rel).parent_path() / name;
        if (fs::is_regular_file(root_ / local)) return local.lexically_normal().generic_string();
        return "";
    }

    void include(const std::string& rel, const Layer& layer, const Include& inc) {
        const std::string shown = inc.angled ? "<" + inc.name + ">" : "\"" + inc.name + "\"";
        const std::string target = inc.angled ? "" : projectFile(rel, inc.name);
        if (target.empty()) {
            library(rel, layer, inc, shown);
            return;
        }
        const Layer* to = owner(table_, target);
        if (to == &layer) return;
        if (!to) {
            add(rel, inc.line, shown, "includes " + target + ", which no layer owns");
            return;
        }
        bool named = false;
        for (const Use& u : layer.mayInclude) {
            if (!names(u, target, *to)) continue;
            if (fromAllowed(u, rel)) return;
            named = true;
        }
        add(rel, inc.line, shown,
            "layer \"" + layer.name + "\" may not include " + target + " (layer \"" + to->name + "\")" +
                (named ? " from this file" : "") + "; it may include " + usesText(layer.mayInclude));
    }

    void library(const std::string& rel, const Layer& layer, const Include& inc, const std::string& shown) {
        // The C++ standard library: <vector>, <cstdio> (no extension, no folder).
        if (inc.angled && inc.name.find_first_of("./") == std::string::npos) return;
        for (const auto& prefix : table_.everywhere)
            if (startsWith(inc.name, prefix)) return;
        bool named = false;
        for (const Use& u : layer.external) {
            if (!startsWith(inc.name, u.what)) continue;
            if (fromAllowed(u, rel)) return;
            named = true;
        }
        add(rel, inc.line, shown,
            "layer \"" + layer.name + "\" may not include the library header " + inc.name + (named ? " from this file" : "") +
                "; its libraries: " + usesText(layer.external));
    }

    const Table& table_;
    fs::path root_;
    std::vector<Violation> violations_;
};

std::string cell(const std::vector<std::string>& items) {
    std::vector<std::string> quoted;
    for (const auto& item : items) quoted.push_back("`" + item + "`");
    return quoted.empty() ? "—" : joined(quoted, ", ");
}

std::string usesCell(const std::vector<Use>& uses) { return uses.empty() ? "—" : usesText(uses); }

}  // namespace

Table loadTable(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot read the layer table");
    json j;
    try {
        j = json::parse(in);
    } catch (const json::parse_error& e) {
        throw std::runtime_error(file.string() + ": " + e.what());
    }
    try {
        if (!j.is_object()) throw std::runtime_error("/: expected an object");
        onlyKeys(j, {"comment", "scanned", "everywhere", "layers"}, "");
        Table t;
        t.scanned = stringsAt(j, "scanned", "");
        t.everywhere = stringsAt(j, "everywhere", "");
        if (!j.contains("layers") || !j["layers"].is_array()) throw std::runtime_error("/layers: expected an array");
        for (std::size_t i = 0; i < j["layers"].size(); ++i) {
            const json& l = j["layers"][i];
            const std::string at = "/layers/" + std::to_string(i);
            if (!l.is_object()) throw std::runtime_error(at + ": expected an object");
            onlyKeys(l, {"name", "files", "role", "target", "may_include", "external", "gl_calls"}, at);
            if (l.contains("gl_calls") && !l["gl_calls"].is_boolean()) throw std::runtime_error(at + "/gl_calls: expected true or false");
            t.layers.push_back({stringAt(l, "name", at), stringsAt(l, "files", at), stringAt(l, "role", at),
                                stringAt(l, "target", at), usesAt(l, "may_include", at), usesAt(l, "external", at),
                                l.value("gl_calls", false)});
        }
        return t;
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(file.string() + ": " + e.what());
    }
}

std::string Violation::text() const {
    return file + ":" + std::to_string(line) + ": " + (include.empty() ? "" : "#include " + include + ": ") + reason;
}

const Layer* owner(const Table& table, const std::string& file) {
    const Layer* best = nullptr;
    std::size_t bestScore = 0;
    for (const Layer& l : table.layers)
        for (const auto& entry : l.files) {
            // A file named exactly beats any folder holding it; a deeper folder beats a shallower one.
            const std::size_t score = entry == file ? entry.size() + 100000
                                      : isFolder(entry) && startsWith(file, entry) ? entry.size()
                                                                                   : 0;
            if (score > bestScore) best = &l, bestScore = score;
        }
    return best;
}

std::vector<Violation> checkTree(const Table& table, const fs::path& root) {
    Checker check(table, root);
    check.table();
    std::vector<std::string> files;
    for (const auto& dir : table.scanned) {
        if (!fs::is_directory(root / dir)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / dir))
            if (entry.is_regular_file() && isSource(entry.path()))
                files.push_back(fs::relative(entry.path(), root).generic_string());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) check.file(f);
    return check.take();
}

std::string markdownTable(const Table& table) {
    std::ostringstream out;
    out << "| layer | files | what it holds | may include (besides its own files) | libraries | GL calls | CMake target |\n"
        << "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const Layer& l : table.layers)
        out << "| **" << l.name << "** | " << cell(l.files) << " | " << l.role << " | " << usesCell(l.mayInclude) << " | "
            << usesCell(l.external) << " | " << (l.glCalls ? "yes" : "no") << " | " << l.target << " |\n";
    out << "\nEvery layer may also include the C++ standard library and " << cell(table.everywhere)
        << ". A file belongs to the layer that names it, else to the one naming its deepest folder.\n";
    return out.str();
}

std::string withTable(const std::string& doc, const Table& table) {
    const auto begin = doc.find(kDocBegin);
    const auto end = doc.find(kDocEnd);
    if (begin == std::string::npos || end == std::string::npos || end < begin)
        throw std::runtime_error(std::string("the doc lacks the markers ") + kDocBegin + " ... " + kDocEnd);
    const auto afterBegin = begin + std::string(kDocBegin).size();
    return doc.substr(0, afterBegin) + "\n" + markdownTable(table) + doc.substr(end);
}

std::vector<std::string> missingFromDiagram(const std::string& doc, const Table& table) {
    const auto section = doc.rfind("## Layers\n", 0) == 0 ? 0 : doc.find("\n## Layers\n");
    const auto open = section == std::string::npos ? section : doc.find("```", section);
    const auto close = open == std::string::npos ? open : doc.find("```", open + 3);
    const std::string diagram = close == std::string::npos ? "" : doc.substr(open, close - open);
    std::vector<std::string> missing;
    for (const Layer& l : table.layers) {
        // A name stands alone in the diagram: "renderer/render" does not count inside "renderer/render/plain".
        const std::regex word("(^|[^A-Za-z0-9_/.-])" + std::regex_replace(l.name, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                              "/?($|[^A-Za-z0-9_/.-])");
        if (!std::regex_search(diagram, word)) missing.push_back(l.name);
    }
    return missing;
}

}  // namespace st::layers
