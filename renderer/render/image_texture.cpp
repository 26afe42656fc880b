#include "renderer/render/image_texture.h"

#include <stdexcept>

namespace st {

void ImageTexture::upload(int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != std::size_t(width) * std::size_t(height) * 4)
        throw std::invalid_argument("ImageTexture: pixel count does not match the size");
    if (!texture_ || width != width_ || height != height_) {
        texture_ = gpu::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(texture_.id(), 1, GL_RGBA8, width, height);
        // One level: the default minification filter would want mipmaps and sample black.
        glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        width_ = width;
        height_ = height;
    }
    // RGBA8 rows are whole multiples of 4 bytes, so the default unpack alignment fits.
    glTextureSubImage2D(texture_.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

}  // namespace st
