#pragma once
// Helpers of the chart tests: a fresh folder per test and the text of an SVG with PLplot's
// character references (&#x54;) decoded.
#include <filesystem>
#include <string>

namespace st::test {

std::filesystem::path freshFolder(const std::string& name);  // under the system temp folder, emptied
std::string svgText(const std::filesystem::path& svg);        // the file with &#xNN; decoded to UTF-8
bool hasTempFiles(const std::filesystem::path& folder);       // any .tmp-* left behind

}  // namespace st::test
