// Issue 39 #10: the Help window's memory table, each GL object's bytes from its size and format.
#include "app/editor/memory_breakdown.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>

using namespace st;
using namespace st::app;

namespace {

std::size_t lineBytes(const std::vector<ui::MemoryLine>& lines, std::string_view what) {
    const auto it = std::find_if(lines.begin(), lines.end(), [&](const ui::MemoryLine& l) { return l.what == what; });
    return it == lines.end() ? 0 : it->bytes;
}

// 1280x720 scene, 4 x 2048 maps in one array, the accuracy pass holding that frame read back.
MemoryInputs knownConfiguration() {
    MemoryInputs in;
    in.scene = {1280, 720};
    in.pip = {320, 180};
    in.maps.storage = CascadeStorage::Array;
    in.maps.textures = {{2048, 2048, 4}};
    in.tileSize = 256;
    in.tiles = 4;
    MeasureHeld m;
    m.what = "Accuracy and probe";
    m.keptPixels = 1280 * 720;
    m.readBackPixels = 1280 * 720;
    m.surface = {1280, 720};
    m.shadow = {1280, 720};
    m.samplesPixels = 1280 * 720;
    in.measures = {m};
    in.overlay = {1280, 720};
    in.vertices = 1000;
    in.indices = 3000;
    in.clusteredIndices = 3000;
    in.images = {{256, 256}};
    return in;
}

}  // namespace

TEST(MemoryBreakdownTest, MipChainCountsEveryLevelDownToOneTexel) {
    EXPECT_EQ(mipChainTexels({256, 256}), 87381u);  // 4^8 + ... + 1
    EXPECT_EQ(mipChainTexels({4, 1}), 7u);          // 4 + 2 + 1
    EXPECT_EQ(mipChainTexels({0, 0}), 0u);
}

// The sum equals the sizes worked out by hand from each object's dimensions and format.
TEST(MemoryBreakdownTest, SumEqualsTheSizesOfAKnownConfiguration) {
    const std::vector<ui::MemoryLine> lines = memoryBreakdown(knownConfiguration());
    const std::size_t px = 1280 * 720;
    EXPECT_EQ(lineBytes(lines, "Shadow maps"), 4u * 2048 * 2048 * 4);              // D32F
    EXPECT_EQ(lineBytes(lines, "Scene view"), px * (4 + 4));                         // RGBA8 + D32F
    EXPECT_EQ(lineBytes(lines, "Side view picture"), 320u * 180 * (4 + 4));
    EXPECT_EQ(lineBytes(lines, "Shadow-map tiles"), 4u * 256 * 256 * 4 + 256 * 256 * 4);  // RGBA8 tiles, R32F raw
    EXPECT_EQ(lineBytes(lines, "Accuracy and probe: kept surfaces"), px * 4 * 16);   // 4 x RGBA32F
    EXPECT_EQ(lineBytes(lines, "Accuracy and probe: pass targets"), px * (16 + 4) + px * 16);
    EXPECT_EQ(lineBytes(lines, "Accuracy and probe: read back (CPU)"), px * (1 + 2 + 4) * 16);
    EXPECT_EQ(lineBytes(lines, "Error overlay"), px * 4);
    EXPECT_EQ(lineBytes(lines, "Scene meshes"), 1000u * 32 + 6000 * 4);
    EXPECT_EQ(lineBytes(lines, "Scene textures"), 87381u * 4);
    const std::size_t byHand = 67108864 + 7372800 + 460800 + 1310720 + 58982400 + 33177600 + 103219200 + 3686400 +
                               56000 + 349524;
    ui::MemoryView view{lines, 0};
    EXPECT_EQ(view.total(), byHand);
    EXPECT_EQ(lines.size(), 10u) << "nothing else, and nothing holding no bytes";
    EXPECT_TRUE(std::is_sorted(lines.begin(), lines.end(),
                               [](const ui::MemoryLine& a, const ui::MemoryLine& b) { return a.bytes > b.bytes; }));
}

// Issue 39 #1: the interactive preview keeps a set of maps of its own beside the full ones; the
// table lists both, the preview's under its own name.
TEST(MemoryBreakdownTest, ThePreviewsOwnMapsAreListedBesideTheFullOnes) {
    MemoryInputs in = knownConfiguration();
    in.previewMaps.storage = CascadeStorage::Array;
    in.previewMaps.textures = {{1024, 1024, 4}};
    const std::vector<ui::MemoryLine> lines = memoryBreakdown(in);
    EXPECT_EQ(lineBytes(lines, "Shadow maps"), 4u * 2048 * 2048 * 4);
    EXPECT_EQ(lineBytes(lines, "Shadow maps (interactive preview)"), 4u * 1024 * 1024 * 4);
    EXPECT_EQ(lines.size(), 11u);
}

TEST(MemoryBreakdownTest, ResidentSetIsReadOnLinux) {
    EXPECT_GT(residentBytes(), std::size_t(1) << 20);
}
