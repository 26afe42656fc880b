#include "app/editor/memory_breakdown.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace st::app {
namespace {

// Bytes per texel of the formats the editor allocates.
constexpr std::size_t kMemRgba8 = 4, kMemD32f = 4, kMemR32f = 4, kMemRgba32f = 16;
constexpr std::size_t kMemVertexBytes = 32;  // renderer/scene/scene.h Vertex: vec3, vec3, vec2
constexpr std::size_t kMemIndexBytes = 4;

std::string memExtentText(Extent e, const char* formats) {
    return std::to_string(e.width) + "x" + std::to_string(e.height) + " " + formats;
}

std::string memMapsText(const csm::StorageLayout& maps) {
    if (maps.textures.empty()) return "";
    const csm::MapTexture& t = maps.textures.front();
    std::string text = maps.textures.size() > 1 ? std::to_string(maps.textures.size()) + " textures, " : "";
    return text + std::to_string(t.layers) + " x " + std::to_string(t.width) + "x" + std::to_string(t.height) + " D32F";
}

void addLine(std::vector<ui::MemoryLine>& lines, std::string what, std::string shape, std::size_t bytes) {
    if (bytes > 0) lines.push_back({std::move(what), std::move(shape), bytes});
}

void addMeasureLines(std::vector<ui::MemoryLine>& lines, const MeasureHeld& m) {
    addLine(lines, m.what + ": kept surfaces", "4 x RGBA32F a pixel, " + std::to_string(m.keptPixels) + " px",
        m.keptPixels * 4 * kMemRgba32f);
    addLine(lines, m.what + ": pass targets", memExtentText(m.surface, "RGBA32F + D32F, shadow RGBA32F"),
        m.surface.pixels() * (kMemRgba32f + kMemD32f) + m.shadow.pixels() * kMemRgba32f);
    addLine(lines, m.what + ": read back (CPU)", "1 to 3 vec4 a pixel kept, 4 a pixel of samples",
        (m.keptPixels + 2 * m.readBackPixels + 4 * m.samplesPixels) * kMemRgba32f);
}

}  // namespace

std::size_t mipChainTexels(Extent e) {
    std::size_t texels = 0;
    for (int w = std::max(e.width, 1), h = std::max(e.height, 1);; w = std::max(w / 2, 1), h = std::max(h / 2, 1)) {
        texels += std::size_t(w) * std::size_t(h);
        if (w == 1 && h == 1) break;
    }
    return e.pixels() ? texels : 0;
}

std::vector<ui::MemoryLine> memoryBreakdown(const MemoryInputs& in) {
    std::vector<ui::MemoryLine> lines;
    addLine(lines, "Shadow maps", memMapsText(in.maps), csm::storageBytes(in.maps));
    addLine(lines, "Shadow maps (interactive preview)", memMapsText(in.previewMaps), csm::storageBytes(in.previewMaps));
    addLine(lines, "Moment maps", "", in.momentBytes);
    addLine(lines, "Screen-space shadow", "", in.screenShadowBytes);
    addLine(lines, "Scene view", memExtentText(in.scene, "RGBA8 + D32F"), in.scene.pixels() * (kMemRgba8 + kMemD32f));
    addLine(lines, "Side view picture", memExtentText(in.pip, "RGBA8 + D32F"), in.pip.pixels() * (kMemRgba8 + kMemD32f));
    addLine(lines, "A/B split: A's image", memExtentText(in.abImage, "RGBA8 + D32F"), in.abImage.pixels() * (kMemRgba8 + kMemD32f));
    const std::size_t tile = std::size_t(in.tileSize) * std::size_t(in.tileSize);
    addLine(lines, "Shadow-map tiles", std::to_string(in.tiles) + " x " + std::to_string(in.tileSize) + "² RGBA8 + R32F",
        tile * (std::size_t(in.tiles) * kMemRgba8 + kMemR32f) + in.atlas.pixels() * kMemRgba8);
    for (const MeasureHeld& m : in.measures) addMeasureLines(lines, m);
    addLine(lines, "Error overlay", memExtentText(in.overlay, "RGBA8"), in.overlay.pixels() * kMemRgba8);
    addLine(lines, "Scene meshes",
        std::to_string(in.vertices) + " vertices, " + std::to_string(in.indices / 3) + " triangles (twice: items, clusters)",
        in.vertices * kMemVertexBytes + (in.indices + in.clusteredIndices) * kMemIndexBytes);
    std::size_t textures = 0;
    for (const Extent& e : in.images) textures += mipChainTexels(e) * kMemRgba8;
    addLine(lines, "Scene textures", std::to_string(in.images.size()) + " SRGB8_A8 with mips", textures);
    std::stable_sort(lines.begin(), lines.end(), [](const ui::MemoryLine& a, const ui::MemoryLine& b) { return a.bytes > b.bytes; });
    return lines;
}

std::size_t residentBytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    unsigned long long size = 0, resident = 0;
    const int read = std::fscanf(f, "%llu %llu", &size, &resident);
    std::fclose(f);
    const long page = ::sysconf(_SC_PAGESIZE);
    return read == 2 && page > 0 ? std::size_t(resident) * std::size_t(page) : 0;
}

}  // namespace st::app
