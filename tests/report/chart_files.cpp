#include "tests/report/chart_files.h"

#include <fstream>
#include <iterator>
#include <unistd.h>

namespace st::test {
namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("st-report-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

namespace {
void appendUtf8(std::string& out, unsigned long cp) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6)), out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += char(0xE0 | (cp >> 12)), out += char(0x80 | ((cp >> 6) & 0x3F)), out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xF0 | (cp >> 18)), out += char(0x80 | ((cp >> 12) & 0x3F));
        out += char(0x80 | ((cp >> 6) & 0x3F)), out += char(0x80 | (cp & 0x3F));
    }
}
}  // namespace

std::string svgText(const fs::path& svg) {
    std::ifstream in(svg, std::ios::binary);
    std::string raw((std::istreambuf_iterator<char>(in)), {}), out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        std::size_t end = raw.find(';', i);
        if (raw.compare(i, 3, "&#x") == 0 && end != std::string::npos && end - i < 12) {
            appendUtf8(out, std::stoul(raw.substr(i + 3, end - i - 3), nullptr, 16));
            i = end;
        } else {
            out += raw[i];
        }
    }
    return out;
}

bool hasTempFiles(const fs::path& folder) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.path().filename().string().rfind(".tmp-", 0) == 0) return true;
    return false;
}

}  // namespace st::test
