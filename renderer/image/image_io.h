#pragma once
// Image files through OpenImageIO, written atomically (temporary file in the same folder, then
// rename) so an interrupted run never leaves a truncated PNG or JSON behind. No GL.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace st {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // top row first, 4 channels
};

// Throws std::runtime_error naming the file and the reason.
void writeImageAtomic(const std::filesystem::path& file, const Rgba8Image& img);
Rgba8Image readImage(const std::filesystem::path& file);  // any format OIIO reads, as RGBA8
void writeTextAtomic(const std::filesystem::path& file, const std::string& text);

}  // namespace st
