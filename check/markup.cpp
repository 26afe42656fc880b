#include "check/markup.h"

#include <cctype>
#include <cstdio>

namespace st::check {

std::string escapeMarkup(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') out += "\xEF\xBF\xBD";
                else out += c;
        }
    }
    return out;
}

std::string safeFileName(std::size_t index, const std::string& name) {
    char prefix[24];
    std::snprintf(prefix, sizeof prefix, "%03zu-", index);
    std::string out = prefix;
    for (char c : name.substr(0, 64)) {
        const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
        out += ok ? c : '_';
    }
    return out;
}

}  // namespace st::check
