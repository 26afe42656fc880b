#include "app/cli/size_option.h"

#include <charconv>
#include <system_error>

namespace st::app {

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
    const auto x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    int w = 0, h = 0;
    const char* end = text.data() + text.size();
    const auto [wEnd, wErr] = std::from_chars(text.data(), text.data() + x, w);
    const auto [hEnd, hErr] = std::from_chars(text.data() + x + 1, end, h);
    const bool whole = wErr == std::errc() && hErr == std::errc() && wEnd == text.data() + x && hEnd == end;
    if (!whole || w < 16 || h < 16 || w > 8192 || h > 8192) return std::nullopt;
    return std::pair{w, h};
}

}  // namespace st::app
