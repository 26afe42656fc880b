#include "renderer/settings/number_text.h"

#include <array>
#include <charconv>
#include <cmath>

namespace st {
namespace {

// Plain decimals (0.0001, 1000000) for everyday magnitudes, exponents (1e+300) beyond them.
template <class T>
std::string shortest(T value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    const T magnitude = std::fabs(value);
    const bool plain = magnitude == T(0) || (magnitude >= T(1e-5) && magnitude < T(1e16));
    std::array<char, 400> buffer{};
    const auto result = plain ? std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                              std::chars_format::fixed)
                              : std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

}  // namespace

std::string formatNumber(double value) { return shortest(value); }

std::string formatFloat(float value) { return shortest(value); }

double tidyFloat(float value) {
    if (!std::isfinite(value)) return static_cast<double>(value);
    const std::string text = formatFloat(value);
    double result = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), result);
    return result;
}

}  // namespace st
