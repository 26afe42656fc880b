#include "report/plot_output.h"

#include "report/chart_fonts.h"
#include "report/palette.h"

#include <plplot.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <tuple>
#include <unistd.h>

namespace st::report::detail {
namespace {
namespace fs = std::filesystem;

std::mutex gPlplotMutex;     // PLplot's current stream and abort handler are process-wide
std::string gAbortMessage;   // written by onAbort() while gPlplotMutex is held

void onAbort(const char* message) {
    if (gAbortMessage.empty()) gAbortMessage = message;
}

// PLplot exit()s on a device it does not know (after asking on stdin), so ask first.
bool deviceAvailable(const char* name) {
    const char* menuStorage[128];
    const char* deviceStorage[128];
    const char** menus = menuStorage;
    const char** devices = deviceStorage;
    int count = 128;  // capacity in, devices found out
    plgDevs(&menus, &devices, &count);
    for (int i = 0; i < count; ++i)
        if (std::strcmp(devices[i], name) == 0) return true;
    return false;
}

// The native "svg" driver writes text as <text> elements (searchable, selectable, and what the
// tests read); svgcairo would turn every glyph into a path.
const char* deviceName(Format format) { return format == Format::Png ? "pngcairo" : "svg"; }

fs::path tempPathFor(const fs::path& file) {
    return file.parent_path() / (".tmp-" + std::to_string(::getpid()) + "-" + file.filename().string());
}

void loadPalette() {
    for (std::size_t i = 0; i < kPalette.size(); ++i) {
        if (i == 0) plscmap0n(int(kPalette.size()));
        plscol0(int(i), kPalette[i].r, kPalette[i].g, kPalette[i].b);
    }
}

// One page on a fresh stream. PLplot closes `out` in plend1(), also when `draw` throws.
void drawPage(std::FILE* out, Format format, int widthPx, int heightPx, const std::function<void()>& draw) {
    PLINT previous = 0, stream = 0;
    plgstrm(&previous);
    plmkstrm(&stream);
    struct EndStream {
        PLINT previous;
        ~EndStream() { plend1(), plsstrm(previous); }
    } end{previous};
    plsdev(deviceName(format));
    plsfile(out);
    plspage(0.0, 0.0, widthPx, heightPx, 0, 0);
    loadPalette();
    plinit();
    pladv(0);
    draw();
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

// Two fixes to PLplot 5.15's svg driver: it names generic families only (chart_fonts.h: these vary
// between machines), the monospace one as "mono-space", which no viewer knows (the front table's
// columns would not line up); and it sizes the page in points, so viewers showed it 4/3 larger
// than the PNG. The families become the PNG's, with the generic one as the viewer's fallback.
bool fixSvg(const fs::path& tmp, int widthPx, int heightPx) {
    std::string text;
    {
        std::ifstream in(tmp, std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), {});
        if (!in) return false;
    }
    for (const auto& [generic, family, fallback] : {std::tuple{"sans-serif", kSansFamily, "sans-serif"},
                                                    std::tuple{"serif", kSerifFamily, "serif"},
                                                    std::tuple{"mono-space", kMonoFamily, "monospace"}})
        replaceAll(text, "font-family=\"" + std::string(generic) + "\"",
                   "font-family=\"'" + std::string(family) + "', " + fallback + "\"");
    for (auto [name, px] : {std::pair{"width", widthPx}, std::pair{"height", heightPx}}) {
        std::string attr = std::string(name) + "=\"" + std::to_string(px);
        if (std::size_t at = text.find(attr + "pt\""); at != std::string::npos) text.erase(at + attr.size(), 2);
    }
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    return bool(out.flush());
}

void fail(const fs::path& file, const fs::path& tmp, const std::string& why) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw std::runtime_error(file.string() + ": cannot write chart: " + why);
}
}  // namespace

void renderPage(const fs::path& file, Format format, int widthPx, int heightPx, const std::function<void()>& draw) {
    std::lock_guard lock(gPlplotMutex);
    nameChartFonts();
    warnAboutMissingChartFonts();
    if (!deviceAvailable(deviceName(format)))
        throw std::runtime_error(file.string() + ": cannot write chart: PLplot has no '" +
                                 deviceName(format) + "' driver (install plplot-driver-cairo)");
    fs::path tmp = tempPathFor(file);
    std::FILE* out = std::fopen(tmp.c_str(), "wb");
    if (!out) throw std::runtime_error(file.string() + ": cannot write chart: " + std::strerror(errno));
    gAbortMessage.clear();
    plsabort(onAbort);
    try {
        drawPage(out, format, widthPx, heightPx, draw);
    } catch (const std::exception& e) {
        fail(file, tmp, e.what());
    }
    plsabort(nullptr);
    std::error_code ec;
    if (!gAbortMessage.empty()) fail(file, tmp, "PLplot: " + gAbortMessage);
    if (fs::file_size(tmp, ec) == 0 || ec) fail(file, tmp, "nothing was written (disk full?)");
    if (format == Format::Svg && !fixSvg(tmp, widthPx, heightPx)) fail(file, tmp, "cannot rewrite the SVG");
    fs::rename(tmp, file, ec);
    if (ec) fail(file, tmp, ec.message());
}

std::string plText(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        out += c;
        if (c == '#') out += '#';
    }
    return out;
}

}  // namespace st::report::detail
