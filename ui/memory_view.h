#pragma once
// Where the editor's memory goes (issue 39 #10: 0.71 GB resident at 1080p, 1.74 GB at 4K, and
// nothing said why): the app's breakdown of the textures and buffers it allocates, as the Help
// window (F1) shows it. Plain values, no GL.
#include <cstddef>
#include <string>
#include <vector>

namespace st::ui {

struct MemoryLine {
    std::string what;   // "Shadow maps"
    std::string shape;  // "4 x 2048² D32F"
    std::size_t bytes = 0;
};

struct MemoryView {
    std::vector<MemoryLine> lines;  // the GL objects, largest first
    std::size_t residentBytes = 0;  // the process's resident set (0: unknown)
    std::size_t total() const {
        std::size_t sum = 0;
        for (const MemoryLine& l : lines) sum += l.bytes;
        return sum;
    }
};

}  // namespace st::ui
