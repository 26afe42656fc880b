// st_figures_doc: prints docs/metrics.md generated from the figure table.
//   st_figures_doc               print it
//   st_figures_doc --write FILE  write it to FILE (docs/metrics.md)
//   st_figures_doc --check FILE  exit 1, saying how to regenerate, if FILE differs (a CTest test)
#include "metrics/figure_table.h"

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

int check(const std::string& file, const std::string& expected) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream actual;
    actual << in.rdbuf();
    if (in && actual.str() == expected) return 0;
    std::cerr << file << (in ? " is stale: it differs from" : " is missing; expected")
              << " the figures doc generated from metrics/figure_table.cpp.\n"
              << "Regenerate it with:  cmake --build <build dir> --target st_update_metrics_doc\n"
              << "(or: <build dir>/tests/metrics/st_figures_doc > docs/metrics.md) and commit it.\n";
    return 1;
}

int write(const std::string& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (out.flush()) return 0;
    std::cerr << "st_figures_doc: cannot write " << file << "\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string text = st::metrics::figuresMarkdown();
    const std::string mode = argc > 1 ? argv[1] : "";
    if (argc == 1) {
        std::cout << text;
        return std::cout ? 0 : 1;
    }
    if (argc == 3 && mode == "--check") return check(argv[2], text);
    if (argc == 3 && mode == "--write") return write(argv[2], text);
    std::cerr << "usage: st_figures_doc [--check FILE | --write FILE]\n";
    return 2;
}
