// The golden folder: a round trip, the per-renderer folder preferred where it exists, and a
// broken golden named with its file.
#include "check/golden_store.h"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace st;
using namespace st::check;

namespace {
fs::path tempDir() {
    const fs::path d = fs::temp_directory_path() / ("st_golden_" + std::to_string(::getpid()) + "_" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(d);
    return d;
}
}  // namespace

TEST(GoldenStoreTest, RendererSlug) {
    EXPECT_EQ(rendererSlug("llvmpipe (LLVM 15.0.6, 256 bits)"), "llvmpipe-llvm-15-0-6-256-bits");
    EXPECT_EQ(rendererSlug("  NVIDIA GeForce RTX 4090/PCIe/SSE2 "), "nvidia-geforce-rtx-4090-pcie-sse2");
    EXPECT_EQ(rendererSlug(""), "unknown-renderer");
}

TEST(GoldenStoreTest, RoundTripAndPerRendererFolder) {
    const fs::path root = tempDir();
    const std::string renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    EXPECT_EQ(goldenDir(root, renderer, "p"), root / "p");
    EXPECT_FALSE(readGolden(root / "p"));  // nothing there: missing, not an error
    Golden g{root / "p", {renderer, "0.1", "abc", "0123456789abcdef", 2, 1}, {2, 1, {1, 2, 3, 255, 4, 5, 6, 255}},
             {{"accuracy", {{"misclassified", 0.25}}}}};
    writeGolden(g);
    const auto back = readGolden(root / "p");
    ASSERT_TRUE(back);
    EXPECT_EQ(back->image.pixels, g.image.pixels);
    EXPECT_EQ(back->figures, g.figures);
    EXPECT_EQ(back->meta.renderer, renderer);
    EXPECT_EQ(back->meta.settingsHash, "0123456789abcdef");
    for (const auto& e : fs::directory_iterator(root / "p")) EXPECT_EQ(e.path().filename().string().rfind(".tmp", 0), std::string::npos);
    fs::create_directories(root / rendererSlug(renderer));
    EXPECT_EQ(goldenDir(root, renderer, "p"), root / "llvmpipe-llvm-15-0-6-256-bits" / "p");
    EXPECT_EQ(goldenDir(root, "other", "p"), root / "p");
    fs::remove_all(root);
}

TEST(GoldenStoreTest, ABrokenGoldenNamesItsFile) {
    const fs::path root = tempDir();
    writeGolden({root / "p", {"r", "0.1", "c", "h", 1, 1}, {1, 1, {0, 0, 0, 255}}, nlohmann::ordered_json::object()});
    std::ofstream(root / "p" / "meta.json") << R"({"renderer": 3})";
    try {
        readGolden(root / "p");
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), (root / "p" / "meta.json").string() + ": /renderer: expected a string");
    }
    fs::remove_all(root);
}
