#include "metrics/alpha_cutout.h"

#include <cmath>

namespace st::metrics {
namespace {
int wrap(int i, int size) { return ((i % size) + size) % size; }

float alphaAt(const Image& img, int x, int y) {
    const std::size_t i = (std::size_t(wrap(y, img.height)) * std::size_t(img.width) + std::size_t(wrap(x, img.width))) * 4 + 3;
    return float(img.rgba[i]) / 255.0f;
}
}  // namespace

float sampleAlpha(const Image& img, glm::vec2 uv) {
    if (img.width <= 0 || img.height <= 0) return 1.0f;
    const float x = uv.x * float(img.width) - 0.5f;
    const float y = uv.y * float(img.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = int(x0), iy = int(y0);
    const float top = (1.0f - fx) * alphaAt(img, ix, iy) + fx * alphaAt(img, ix + 1, iy);
    const float bottom = (1.0f - fx) * alphaAt(img, ix, iy + 1) + fx * alphaAt(img, ix + 1, iy + 1);
    return (1.0f - fy) * top + fy * bottom;
}

float materialAlpha(const Scene& scene, const Material& m, glm::vec2 uv) {
    const bool textured = m.baseColorTexture >= 0 && m.baseColorTexture < int(scene.images.size());
    return m.baseColor.a * (textured ? sampleAlpha(scene.images[std::size_t(m.baseColorTexture)], uv) : 1.0f);
}

bool cutOut(const Scene& scene, const Material& m, glm::vec2 uv) {
    return m.alphaMask && materialAlpha(scene, m, uv) < m.alphaCutoff;
}

}  // namespace st::metrics
