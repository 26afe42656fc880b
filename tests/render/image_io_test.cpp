// readImage must read what is on disk now, even after the same path was read and then rewritten
// in this process (OIIO's ImageCache kept the first spec and overflowed the smaller buffer).
#include "renderer/image/image_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using namespace st;

namespace {
Rgba8Image solid(int w, int h, std::uint8_t r) {
    Rgba8Image img{w, h, {}};
    img.pixels.assign(std::size_t(w) * h * 4, 255);
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) img.pixels[i] = r;
    return img;
}
}  // namespace

TEST(ImageIoTest, RereadsAFileRewrittenInTheSameProcess) {
    auto dir = std::filesystem::temp_directory_path() / ("st-image-io-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    auto file = dir / "img.png";
    writeImageAtomic(file, solid(8, 4, 10));
    Rgba8Image first = readImage(file);
    ASSERT_EQ(first.width, 8);
    EXPECT_EQ(first.pixels[0], 10);
    writeImageAtomic(file, solid(16, 12, 200));
    Rgba8Image second = readImage(file);
    EXPECT_EQ(second.width, 16);
    EXPECT_EQ(second.height, 12);
    ASSERT_EQ(second.pixels.size(), 16u * 12u * 4u);
    EXPECT_EQ(second.pixels[0], 200);
    EXPECT_EQ(second.pixels.back(), 255);
    std::filesystem::remove_all(dir);
}

TEST(ImageIoTest, MissingFileNamesThePath) {
    try {
        readImage("/nonexistent/shadowtune/missing.png");
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
    }
}
