// Images: tinygltf hands over the encoded bytes; only base colour textures are decoded, here, with
// stb_image from Debian's libstb-dev compiled privately into this file (STB_IMAGE_STATIC), so the
// size is read from the header and checked before any pixel memory is allocated.
#include "renderer/scene/gltf_detail.h"

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

std::string failureReason() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr ? reason : "unknown error";
}

}  // namespace

std::optional<Image> decodeImage(LoadContext& ctx, const tinygltf::Image& image, int index) {
    const std::string label = imageLabel(image, index);
    const std::string fallback = "; its materials use their base colour factor";
    if (auto it = ctx.unreadableImages.find(index); it != ctx.unreadableImages.end()) {
        ctx.warn(label + ": " + it->second + fallback);
        return std::nullopt;
    }
    if (!image.as_is || image.image.empty() || image.image.size() > INT_MAX) {
        ctx.warn(label + " could not be read" + fallback);
        return std::nullopt;
    }
    const auto* bytes = reinterpret_cast<const stbi_uc*>(image.image.data());
    const int size = static_cast<int>(image.image.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
        ctx.warn(label + " cannot be decoded (" + failureReason() + ")" + fallback);
        return std::nullopt;
    }
    const int maxSide = ctx.limits.maxImageDimension;
    if (width < 1 || height < 1 || width > maxSide || height > maxSide) {
        ctx.warn(label + " is " + std::to_string(width) + "x" + std::to_string(height) + ", outside 1.." +
                 std::to_string(maxSide) + " (GltfLimits::maxImageDimension)" + fallback);
        return std::nullopt;
    }
    const std::uint64_t rgbaBytes = std::uint64_t(width) * std::uint64_t(height) * 4;
    if (rgbaBytes > ctx.limits.maxDecodedBytes - std::min(ctx.decodedBytes, ctx.limits.maxDecodedBytes)) {
        ctx.warn(label + " would take the decoded scene above " + std::to_string(ctx.limits.maxDecodedBytes) +
                 " bytes (GltfLimits::maxDecodedBytes)" + fallback);
        return std::nullopt;
    }
    int decodedWidth = 0, decodedHeight = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes, size, &decodedWidth, &decodedHeight, &channels, 4);
    if (pixels != nullptr && (decodedWidth != width || decodedHeight != height)) {
        stbi_image_free(pixels);  // the header said otherwise: trust neither
        pixels = nullptr;
    }
    if (pixels == nullptr) {
        ctx.warn(label + " cannot be decoded (" + failureReason() + ")" + fallback);
        return std::nullopt;
    }
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels, pixels + rgbaBytes);
    stbi_image_free(pixels);
    ctx.decodedBytes += rgbaBytes;
    return out;
}

}  // namespace st::gltf
