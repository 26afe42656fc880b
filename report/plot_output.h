#pragma once
// One PLplot page into one file (report/ internals). PLplot keeps its state in globals (the current
// stream, the abort handler), so every page is drawn under one mutex on a stream of its own that
// plend1() frees; nothing of one chart leaks into the next, and a PNG and an SVG of one chart are
// two independent pages.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace st::report::detail {

enum class Format { Png, Svg };

// Writes `file` atomically (.tmp-<pid>-<name> in the same folder, then rename): `draw` runs after
// plinit() and pladv(0) with the chart palette (palette.h) loaded. Throws std::runtime_error naming
// `file` when the folder is not writable, the driver is missing or PLplot reports an error; no
// temporary file is left behind.
void renderPage(const std::filesystem::path& file, Format format, int widthPx, int heightPx,
                const std::function<void()>& draw);

// PLplot reads '#' as the start of an escape sequence ("#u" superscript, "#<...>" font): text from
// the caller is escaped so it prints as written.
std::string plText(std::string_view text);

}  // namespace st::report::detail
