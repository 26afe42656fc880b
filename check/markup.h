#pragma once
// Text from presets and suites put into HTML and XML: every string is escaped, so a preset named
// `<img src=x onerror=alert(1)>` is shown as text and injects nothing. No GL.
#include <string>

namespace st::check {

// & < > " ' as entities; control characters XML 1.0 forbids become U+FFFD (valid in text and
// attributes of both HTML and XML).
std::string escapeMarkup(const std::string& text);

// A folder or file name made of [A-Za-z0-9._-] only (others become '_'), with `index` in front
// so two names that map to the same text stay apart: "03-_img_src_x...".
std::string safeFileName(std::size_t index, const std::string& name);

}  // namespace st::check
