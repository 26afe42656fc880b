#include "report/front_table.h"

#include "report/palette.h"
#include "report/plot_output.h"

#include <plplot.h>

#include <algorithm>
#include <cstdlib>

namespace st::report::detail {
namespace {

constexpr double kTableFont = 15, kLineHeight = 22, kCaptionHeight = 34;

std::size_t codePoints(const std::string& s) {
    return std::size_t(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

bool isNumber(const std::string& s) {
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return !s.empty() && end && (*end == '\0' || *end == '%' || *end == ' ');
}

struct Column {
    std::size_t width = 0;
    bool right = true;  // numbers are right-aligned so their digits line up
};

std::vector<Column> columns(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    std::vector<Column> cols(header.size());
    for (std::size_t c = 0; c < cols.size(); ++c) cols[c].width = codePoints(header[c]);
    for (const auto& row : rows)
        for (std::size_t c = 0; c < std::min(row.size(), cols.size()); ++c) {
            cols[c].width = std::max(cols[c].width, codePoints(row[c]));
            cols[c].right = cols[c].right && isNumber(row[c]);
        }
    return cols;
}

std::string line(const std::vector<Column>& cols, const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t c = 0; c < cols.size(); ++c) {
        std::string cell = c < cells.size() ? cells[c] : "";
        std::string pad(cols[c].width - std::min(cols[c].width, codePoints(cell)), ' ');
        out += (c ? "   " : "") + (cols[c].right ? pad + cell : cell + pad);
    }
    return plText(out);
}
}  // namespace

double frontTableHeightPx(const Frame& frame, std::size_t rows) {
    if (rows == 0) return 0;
    std::size_t lines = std::min(rows, kMaxTableRows) + 1 + (rows > kMaxTableRows ? 1 : 0);
    return frame.px(kCaptionHeight + kLineHeight * double(lines) + 16);
}

void drawFrontTable(const Frame& f, double topPx, const std::vector<std::string>& header,
                    const std::vector<std::vector<std::string>>& rows) {
    if (rows.empty()) return;
    std::vector<Column> cols = columns(header, rows);
    usePageCoordinates(f);
    double x = f.plot.x0, y = topPx + f.px(kCaptionHeight / 2);
    plcol0(kInk);
    setTextPx(f, kTableFont + 2);
    pageText(f, x, y, 0.0, "Pareto front (" + std::to_string(rows.size()) + (rows.size() == 1 ? " point)" : " points)"));
    y += f.px(kCaptionHeight / 2 + kLineHeight / 2);
    plsfont(PL_FCI_MONO, -1, PL_FCI_BOLD);
    setTextPx(f, kTableFont);
    pageText(f, x, y, 0.0, line(cols, header));
    plsfont(PL_FCI_MONO, -1, PL_FCI_MEDIUM);
    double ruleEnd = std::min(f.plot.x1, x + 0.61 * f.px(kTableFont) * double(codePoints(line(cols, header))));
    PLFLT lx[2] = {x, ruleEnd}, ly[2] = {f.height - (y + f.px(kLineHeight / 2)), f.height - (y + f.px(kLineHeight / 2))};
    plcol0(kMutedInk);
    plwidth(1.0);
    plline(2, lx, ly);
    plcol0(kInk);
    for (std::size_t r = 0; r < std::min(rows.size(), kMaxTableRows); ++r)
        pageText(f, x, y += f.px(kLineHeight), 0.0, line(cols, rows[r]));
    plcol0(kMutedInk);
    if (rows.size() > kMaxTableRows)
        pageText(f, x, y += f.px(kLineHeight), 0.0, "... " + std::to_string(rows.size() - kMaxTableRows) + " more");
    plsfont(PL_FCI_SANS, -1, PL_FCI_MEDIUM);
}

}  // namespace st::report::detail
