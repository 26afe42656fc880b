#pragma once
// The front table under a scatter chart (report/ internals): a header and one row per front
// point in a monospace font, at most kMaxTableRows rows and a "... N more" line.
#include "report/chart_frame.h"

#include <string>
#include <vector>

namespace st::report::detail {

inline constexpr std::size_t kMaxTableRows = 25;

double frontTableHeightPx(const Frame& frame, std::size_t rows);  // 0 without rows
void drawFrontTable(const Frame& frame, double topPx, const std::vector<std::string>& header,
                    const std::vector<std::vector<std::string>>& rows);

}  // namespace st::report::detail
