// Images: tinygltf hands over the encoded bytes; only base colour textures are decoded, here, with
// stb_image from Debian's libstb-dev compiled privately into this file (STB_IMAGE_STATIC), so the
// size is read from the header and checked before any pixel memory is allocated.
#include "renderer/scene/gltf_detail.h"
#include "renderer/scene/jpeg_tables.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <climits>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS (1 << 16)  // a backstop: GltfLimits::maxImageDimension is checked first
#include <stb/stb_image.h>

namespace st::gltf {

bool keepEncodedImage(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;  // never fail the load for an image: decodeImage warns instead
}

namespace {

std::string imageLabel(const tinygltf::Image& image, int index) {
    std::string label = "image " + std::to_string(index);
    if (!image.uri.empty() && image.uri.size() <= 80) label += " ('" + image.uri + "')";
    else if (!image.name.empty()) label += " ('" + image.name + "')";
    return label;
}

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// Size from the header: PNG's IHDR read here (stb refuses above 2^30 bytes without saying why),
// the rest through stb. False: not an image stb can read.
bool imageSize(const std::vector<unsigned char>& bytes, std::int64_t& width, std::int64_t& height) {
    static const std::uint8_t pngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() >= 24 && std::equal(pngSignature, pngSignature + 8, bytes.begin())) {
        width = bigEndian32(bytes.data() + 16);
        height = bigEndian32(bytes.data() + 20);
        return true;
    }
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels)) return false;
    width = w;
    height = h;
    return true;
}

std::string failureReason() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr ? reason : "unknown error";
}

const char* const kFallback = "; its materials use their base colour factor";

// The size of an image that may be decoded, or nullopt (warned): unreadable, or above the limits.
std::optional<glm::ivec2> checkedSize(LoadContext& ctx, const tinygltf::Image& image, int index,
                                      const std::string& label) {
    if (auto it = ctx.unreadableImages.find(index); it != ctx.unreadableImages.end()) {
        ctx.warn(label + ": " + it->second + kFallback);
        return std::nullopt;
    }
    std::int64_t width = 0, height = 0;
    if (!image.as_is || image.image.empty() || image.image.size() > INT_MAX) {
        ctx.warn(label + " could not be read" + kFallback);
    } else if (!jpegHuffmanTablesFit(image.image.data(), image.image.size())) {
        ctx.warn(label + " is a corrupt JPEG (a Huffman table with more than 256 codes)" + kFallback);
    } else if (!imageSize(image.image, width, height)) {
        ctx.warn(label + " cannot be decoded (" + failureReason() + ")" + kFallback);
    } else if (const int maxSide = ctx.limits.maxImageDimension;
               width < 1 || height < 1 || width > maxSide || height > maxSide) {
        ctx.warn(label + " is " + std::to_string(width) + "x" + std::to_string(height) + ", outside 1.." +
                 std::to_string(maxSide) + " (GltfLimits::maxImageDimension)" + kFallback);
    } else if (std::uint64_t(width * height * 4) >
               ctx.limits.maxDecodedBytes - std::min(ctx.decodedBytes, ctx.limits.maxDecodedBytes)) {
        ctx.warn(label + " would take the decoded scene above " + std::to_string(ctx.limits.maxDecodedBytes) +
                 " bytes (GltfLimits::maxDecodedBytes)" + kFallback);
    } else {
        return glm::ivec2(static_cast<int>(width), static_cast<int>(height));
    }
    return std::nullopt;
}

}  // namespace

std::optional<Image> decodeImage(LoadContext& ctx, const tinygltf::Image& image, int index) {
    const std::string label = imageLabel(image, index);
    const std::optional<glm::ivec2> size = checkedSize(ctx, image, index, label);
    if (!size) return std::nullopt;
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(image.image.data(), static_cast<int>(image.image.size()), &width,
                                            &height, &channels, 4);
    if (pixels != nullptr && (width != size->x || height != size->y)) {
        stbi_image_free(pixels);  // the header said otherwise: trust neither
        pixels = nullptr;
    }
    if (pixels == nullptr) {
        ctx.warn(label + " cannot be decoded (" + failureReason() + ")" + kFallback);
        return std::nullopt;
    }
    const std::size_t bytes = std::size_t(width) * std::size_t(height) * 4;
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels, pixels + bytes);
    stbi_image_free(pixels);
    ctx.decodedBytes += bytes;
    return out;
}

}  // namespace st::gltf
