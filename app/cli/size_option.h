#pragma once
// The `--size WxH` option of the headless commands.
#include <optional>
#include <string>
#include <utility>

namespace st::app {

// "WxH" -> {W, H}, each 16..8192; nullopt for anything else. Parsed by hand: <regex> trips
// GCC 12's -Wmaybe-uninitialized in sanitizer builds.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

}  // namespace st::app
