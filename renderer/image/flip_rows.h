#pragma once
// GL read-backs start with the bottom row; images and samples here are stored top row first.
// The one place that turns one into the other. Header-only, pure: no GL.
#include <algorithm>
#include <cstddef>
#include <span>

namespace st {

// Reverses the order of the rows of `pixels`, each `rowElements` elements long (4 per pixel for
// RGBA8 bytes, 1 per pixel for vec4 samples). A trailing partial row is left in place.
template <class T>
void flipRows(std::span<T> pixels, std::size_t rowElements) {
    if (rowElements == 0) return;
    const std::size_t rows = pixels.size() / rowElements;
    for (std::size_t top = 0, bottom = rows; top + 1 < bottom; ++top) {
        --bottom;
        std::swap_ranges(pixels.begin() + top * rowElements, pixels.begin() + (top + 1) * rowElements,
                         pixels.begin() + bottom * rowElements);
    }
}

}  // namespace st
