// st_layers: the layer table (docs/layers.json) against the tree and against the architecture doc.
//   st_layers ROOT --check-includes   every #include of app/ ui/ metrics/ sweep/ report/ renderer/
//                                     shaders/ against the table; exit 1 listing file:line and rule
//   st_layers ROOT --check-doc        exit 1 if docs/architecture.md's Layers table is not the one
//                                     generated from the table, or its diagram misses a layer
//   st_layers ROOT --write-doc        regenerate that table in docs/architecture.md
//   --table FILE                      another table than ROOT/docs/layers.json
#include "tests/layers/layer_table.h"

#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {
namespace fs = std::filesystem;
using namespace st::layers;

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": cannot read");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

int checkIncludes(const Table& table, const fs::path& root) {
    const auto violations = checkTree(table, root);
    for (const auto& v : violations) std::cerr << v.text() << "\n";
    if (violations.empty()) return 0;
    std::cerr << violations.size() << " violation(s) of the layer table docs/layers.json"
              << " (docs/architecture.md#layers): move the code down a layer, or change the table if the layering changed.\n";
    return 1;
}

int checkDoc(const Table& table, const fs::path& doc) {
    const std::string text = readFile(doc);
    int failures = 0;
    if (withTable(text, table) != text) {
        std::cerr << doc.string() << ": the Layers table differs from the one generated from docs/layers.json.\n"
                  << "Regenerate it with:  cmake --build --preset release --target st_update_layers_doc  and commit it.\n";
        ++failures;
    }
    for (const auto& name : missingFromDiagram(text, table)) {
        std::cerr << doc.string() << ": the Layers diagram does not name the layer " << name << " of docs/layers.json.\n";
        ++failures;
    }
    return failures ? 1 : 0;
}

int writeDoc(const Table& table, const fs::path& doc) {
    const std::string text = withTable(readFile(doc), table);
    const fs::path tmp = doc.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush()) throw std::runtime_error(tmp.string() + ": cannot write");
    }
    fs::rename(tmp, doc);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc < 3) throw std::runtime_error("usage: st_layers ROOT --check-includes|--check-doc|--write-doc [--table FILE]");
        const fs::path root = argv[1];
        const std::string mode = argv[2];
        fs::path tableFile = root / "docs/layers.json";
        if (argc == 5 && std::string(argv[3]) == "--table") tableFile = argv[4];
        else if (argc != 3) throw std::runtime_error("st_layers: unexpected arguments after " + mode);
        const Table table = loadTable(tableFile);
        const fs::path doc = root / "docs/architecture.md";
        if (mode == "--check-includes") return checkIncludes(table, root);
        if (mode == "--check-doc") return checkDoc(table, doc);
        if (mode == "--write-doc") return writeDoc(table, doc);
        throw std::runtime_error("st_layers: unknown mode " + mode);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 2;
    }
}
