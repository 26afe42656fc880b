#pragma once
// The layer table (docs/layers.json) and the check of every #include against it: which layer a
// file belongs to, which layers and libraries it may include, and the Layers table of
// docs/architecture.md generated from it. Used by st_layers (the CTest checks) and its unit tests.
#include <filesystem>
#include <string>
#include <vector>

namespace st::layers {

// A layer this one may include; `from`, when not empty, limits that to the listed files.
struct Use {
    std::string what;               // a layer's name, or a path: a file, or a folder ending in '/'
    std::vector<std::string> from;  // files of this layer allowed to include it (empty: all)
};

struct Layer {
    std::string name;
    std::vector<std::string> files;     // folders (ending in '/') and files it owns
    std::string role;                   // what it holds, one line
    std::string target;                 // its CMake target(s)
    std::vector<Use> mayInclude;        // other layers (or their files)
    std::vector<Use> external;          // include-name prefixes of libraries: "glm/", "imgui"
    bool glCalls = false;               // may call GL (gl*() functions) itself
};

struct Table {
    std::vector<std::string> scanned;   // top-level folders whose files are checked
    std::vector<std::string> everywhere;  // library prefixes any layer may include (POSIX)
    std::vector<Layer> layers;
};

// Throws std::runtime_error naming the file and the JSON path on a malformed table.
Table loadTable(const std::filesystem::path& file);

// One #include against the table, or a file no layer owns: "file:line: reason".
struct Violation {
    std::string file;  // relative to the root, '/'-separated
    int line = 0;
    std::string include;
    std::string reason;
    std::string text() const;
};

// The layer owning `file` (root-relative): the longest matching entry; nullptr if none.
const Layer* owner(const Table& table, const std::string& file);

// Every include of every source file (.h .hpp .cpp .glsl .vert .frag .comp) under the scanned
// folders of `root`, checked against the table; GL calls (glFoo() outside comments and strings)
// in layers without gl_calls; and table entries naming nothing in the tree.
std::vector<Violation> checkTree(const Table& table, const std::filesystem::path& root);

// The markdown table of docs/architecture.md's Layers section, and the section's markers.
std::string markdownTable(const Table& table);
inline constexpr const char* kDocBegin =
    "<!-- layers:begin: generated from docs/layers.json by `cmake --build --preset release --target st_update_layers_doc`; do not edit -->";
inline constexpr const char* kDocEnd = "<!-- layers:end -->";

// `doc` with the text between the markers replaced by markdownTable(table); throws when the
// markers are missing.
std::string withTable(const std::string& doc, const Table& table);

// Layer names the first ``` block after the doc's "## Layers" heading does not mention.
std::vector<std::string> missingFromDiagram(const std::string& doc, const Table& table);

}  // namespace st::layers
